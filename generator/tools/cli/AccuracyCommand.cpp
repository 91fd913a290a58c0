// `rbdgen accuracy ROBOT.urdf --out DIR`: what accuracy costs in time (docs/ACCURACY.md).
#include <iostream>
#include <memory>

#include "../accuracy/Study.h"
#include "Command.h"
#include "RobotOptions.h"

namespace rbdgen::cli
{

Command addAccuracyCommand(CLI::App & app)
{
  struct Options
  {
    RobotOptions robot;
    accuracy::StudyOptions study;
  };
  auto o = std::make_shared<Options>();
  CLI::App * cmd = app.add_subcommand(
      "accuracy", "time and error of each variant (float/double, generated/runtime, ABA/CRBA, integrators x steps) "
                  "against a long double reference; writes DIR/accuracy.{md,csv} and plots");
  o->robot.addTo(*cmd, false);
  cmd->add_option("--scene", o->study.scene, "scene file: its robot, effects and initial state for the simulation study")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", o->study.outDir, "output directory")->required();
  cmd->add_option("--states", o->study.states, "number of seeded random states (default 1000)")
      ->check(CLI::Range(1, 1000000));
  cmd->add_option("--seed", o->study.seed, "seed of the random states (default 1)");
  cmd->add_option("--cxx", o->study.cxx, "C++ compiler for the generated variants (default: $CXX, else rbdgen's)");
  cmd->add_option("--horizon", o->study.sim.horizon, "simulated time of the integrator study, s (default 1)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("!--no-simulation", o->study.simulation, "skip the integrator study");
  cmd->add_flag("!--no-derivatives", o->study.derivatives,
                "skip the derivatives (the generated header is then compiled without them)");
  cmd->add_flag("!--no-plots", o->study.plots, "do not run gnuplot (the .dat and .gp files are still written)");
  return {cmd,
          [o] {
            if(o->robot.urdf.empty() && o->study.scene.empty())
              throw std::runtime_error("accuracy: give a URDF or --scene");
            o->study.urdf = o->robot.urdf;
            o->study.floatingBase = o->robot.floatingBase;
            o->study.baseLink = o->robot.baseLink;
            for(const auto & path : accuracy::runStudy(o->study)) std::cout << path << "\n";
            return 0;
          },
          [o] { return o->robot.urdf.empty() ? o->study.scene : o->robot.urdf; }};
}

} // namespace rbdgen::cli
