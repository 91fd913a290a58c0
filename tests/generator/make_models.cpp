// Build tool of the tests: emit the generated header of every programmatic model.
//   make_models OUTDIR   ->  OUTDIR/<name>/dynamics.hpp
#include <cstdio>
#include <exception>

#include "Generate.h"
#include "emit/Header.h"
#include "ProgrammaticModels.h"

int main(int argc, char ** argv)
{
  if(argc != 2)
  {
    std::fprintf(stderr, "usage: make_models OUTDIR\n");
    return 2;
  }
  try
  {
    std::vector<rbdgen::GeneratedFile> files;
    for(int k = 0; k < rbdgentest::programmaticModelCount(); ++k)
    {
      const rbdgentest::ProgrammaticModel m = rbdgentest::programmaticModel(k);
      const std::vector<sva::PTransformd> identity(static_cast<std::size_t>(m.mb.nrBodies()), sva::PTransformd::Identity());
      const rbdgen::RobotModel rm = rbdgen::buildRobotModel(m.mb, identity, m.name);
      files.push_back({m.name + "/dynamics.hpp", rbdgen::emit::emitDynamicsHeader(
                                                   rm, rbdgen::emit::plainHeaderSpec(
                                                           rm, m.name,
                                                           rbdgen::emit::plainProvenance(rm, "programmatic model " + m.name, "-",
                                                                                         "in code, derivatives"),
                                                           true))});
    }
    rbdgen::writeFiles(argv[1], files);
  }
  catch(const std::exception & e)
  {
    std::fprintf(stderr, "make_models: %s\n", e.what());
    return 1;
  }
  return 0;
}
