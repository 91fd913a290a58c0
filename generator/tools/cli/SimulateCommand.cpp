// `rbdgen simulate SCENE.xml [--duration T] [--dt DT] [--integrator NAME] [--out traj.csv]
// [--plot traj.png] [--no-plot]`: run the scene with the runtime, write CSV + gnuplot plot.
#include <iostream>
#include <memory>

#include "../simulate/Simulate.h"
#include "Command.h"

namespace rbdgen::cli
{

Command addSimulateCommand(CLI::App & app)
{
  struct Options
  {
    std::string scene, integrator, csv, png;
    double duration = 0, dt = 0;
    bool noPlot = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App * cmd = app.add_subcommand("simulate", "run a scene (runtime, zero torque or the scene's PD hold); write the "
                                                  "trajectory as CSV and plot it (gnuplot)");
  cmd->add_option("scene", o->scene, "scene file (docs/SCENES.md)")->required();
  cmd->add_option("--duration", o->duration, "simulated time in s (default: the scene's)");
  cmd->add_option("--dt", o->dt, "time step in s (default: the scene's)");
  cmd->add_option("--integrator", o->integrator, "semi_implicit_euler | explicit_euler | rk4 (default: the scene's)");
  cmd->add_option("--out", o->csv, "trajectory CSV (default: <scene stem>.csv)");
  cmd->add_option("--plot", o->png, "plot PNG (default: the CSV path with .png); the gnuplot script goes beside the CSV");
  cmd->add_flag("--no-plot", o->noPlot, "write the CSV only");
  return {cmd,
          [o, cmd] {
            simulate::SimulateOptions opt;
            opt.scene = o->scene;
            if(cmd->count("--duration")) opt.duration = o->duration;
            if(cmd->count("--dt")) opt.dt = o->dt;
            if(cmd->count("--integrator")) opt.integrator = simulate::parseIntegrator(o->integrator);
            opt.csv = o->csv;
            opt.png = o->png;
            opt.plot = !o->noPlot;
            const simulate::SimulateResult r = simulate::runSimulation(opt, std::cerr);
            for(const std::string & w : r.warnings) std::cerr << "rbdgen: warning: " << w << "\n";
            std::cout << r.csv << " (" << r.rows << " rows, " << r.steps << " steps; total energy " << r.energyStart
                      << " -> " << r.energyEnd << " J)\n";
            if(!o->noPlot) std::cout << r.gp << "\n";
            if(!r.png.empty()) std::cout << r.png << "\n";
            return 0;
          },
          [o] { return o->scene; }};
}

} // namespace rbdgen::cli
