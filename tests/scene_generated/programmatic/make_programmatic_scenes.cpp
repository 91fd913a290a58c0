// Build tool of the tests: `make_programmatic_scenes OUTDIR` writes OUTDIR/<ns>/dynamics.hpp, the
// scene header of the programmatic scene (ProgrammaticScene.h) for each integrator.
#include <cstdio>
#include <exception>

#include "Generate.h"
#include "ProgrammaticScene.h"
#include "emit/SceneHeader.h"

int main(int argc, char ** argv)
{
  if(argc != 2)
  {
    std::fprintf(stderr, "usage: make_programmatic_scenes OUTDIR\n");
    return 2;
  }
  try
  {
    const rbd::scene::SceneRobot sr = sgprog::sceneRobot();
    const std::vector<sva::PTransformd> identity(static_cast<std::size_t>(sr.robot.mb.nrBodies()), sva::PTransformd::Identity());
    const rbdgen::RobotModel rm = rbdgen::buildRobotModel(sr.robot.mb, identity, "prog_scene");
    std::vector<rbdgen::GeneratedFile> files;
    for(int k = 0; k < sgprog::kIntegrators; ++k)
    {
      const std::string ns = sgprog::headerName(k);
      const rbd::scene::Scene scene = sgprog::scene(sgprog::integrator(k));
      const std::string provenance = "// programmatic scene (tests/scene_generated/programmatic)";
      files.push_back({ns + "/dynamics.hpp",
                       rbdgen::emit::emitDynamicsHeader(rm, rbdgen::emit::sceneHeaderSpec(rm, scene, sr, ns, provenance))});
    }
    rbdgen::writeFiles(argv[1], files);
  }
  catch(const std::exception & e)
  {
    std::fprintf(stderr, "make_programmatic_scenes: %s\n", e.what());
    return 1;
  }
  return 0;
}
