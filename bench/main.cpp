// Bench program of one robot (RBDGEN_BENCH_ROBOT, RBDGEN_BENCH_URDF, RBDGEN_BENCH_FLOATING set by
// bench/CMakeLists.txt): agreement checks of every implementation against the runtime, then the
// timed cells "<robot>/<algorithm>/<implementation>" (ns per call).
//
//   bench_<robot> [--check-only] [google benchmark options]   exit 1 if an implementation disagrees
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "common/BenchCase.h"
#include "common/Checks.h"
#include "common/Derivatives.h"
#include "common/RuntimeBench.h"
#include "generated/GeneratedBench.h"
#include "peers/Peers.h"

int main(int argc, char ** argv)
{
  bool checkOnly = false;
  std::vector<char *> args;
  for(int i = 0; i < argc; ++i)
  {
    if(std::strcmp(argv[i], "--check-only") == 0)
      checkOnly = true;
    else
      args.push_back(argv[i]);
  }
  int nargs = static_cast<int>(args.size());

  rbdbench::BenchCase c;
  try
  {
    c = rbdbench::loadCase(RBDGEN_BENCH_ROBOT, RBDGEN_BENCH_URDF, RBDGEN_BENCH_FLOATING);
  }
  catch(const std::exception & e)
  {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }

  rbdbench::CheckLog log;
  rbdbench::checkDerivativesReference(c, log);
  rbdbench::registerGenerated(c, log);
  rbdbench::registerRuntime(c, log);
  rbdbench::registerPeers(c, log);

  benchmark::Initialize(&nargs, args.data());
  if(benchmark::ReportUnrecognizedArguments(nargs, args.data())) return 1;
  benchmark::AddCustomContext("robot", c.name);
  benchmark::AddCustomContext("urdf", c.urdf);
  benchmark::AddCustomContext("floating", c.floating ? "yes" : "no");
  benchmark::AddCustomContext("nq", std::to_string(c.model.mb.nrParams()));
  benchmark::AddCustomContext("nv", std::to_string(c.model.mb.nrDof()));
  benchmark::AddCustomContext("nbodies", std::to_string(c.model.mb.nrBodies()));
  benchmark::AddCustomContext("jacobian_body", c.jacobianBodyName);
  benchmark::AddCustomContext("fd_algorithm", rbdbench::generatedForwardDynamicsAlgorithm());
  benchmark::AddCustomContext("compiler", RBDGEN_BENCH_COMPILER);
  log.publish(c.name);
  if(checkOnly) return log.allOk() ? 0 : 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return log.allOk() ? 0 : 1;
}
