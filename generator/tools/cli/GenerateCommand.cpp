// `rbdgen generate ROBOT.urdf --out DIR` or `rbdgen generate --scene SCENE.xml --out DIR`: emit
// NS/dynamics.hpp (plain, or specialised to the scene's effects), and NS/batch.hpp with --batch.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "Generate.h"
#include "Command.h"
#include "RobotOptions.h"

namespace rbdgen::cli
{

Command addGenerateCommand(CLI::App & app)
{
  struct Options
  {
    RobotOptions robot;
    std::string outDir, ns, scene, depfile;
    bool strict = false;
    bool derivatives = false;
    bool independentMimic = false;
    bool instantiate = false;
    bool batch = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App * cmd = app.add_subcommand("generate", "emit NS/dynamics.hpp for the robot (or the scene) into --out DIR");
  o->robot.addTo(*cmd, false);
  cmd->add_option("--scene", o->scene, "scene file: the header is specialised to its effects (the URDF and base come "
                                       "from the scene; no URDF argument then)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", o->outDir, "output directory")->required();
  cmd->add_option("--namespace", o->ns, "C++ namespace (default: the scene or robot name, sanitised)");
  cmd->add_flag("--strict", o->strict, "mass matrix hazards are errors, not warnings: joints moving only massless links, two free joints with "
                                    "a massless link between them (singular), dofs of negligible effective inertia (ill-conditioned)");
  cmd->add_flag("--derivatives", o->derivatives,
                "also emit inverse_dynamics_derivatives(q, alpha, alphaD) and forward_dynamics_derivatives(q, alpha, tau) "
                "(d/dq in the tangent space, d/dalpha, M^-1); with --scene, as its <derivatives/> output");
  cmd->add_flag("--independent-mimic", o->independentMimic,
                "mimic joints as independent joints with their own dofs (default: coupled to the joints they follow, "
                "q = multiplier q_followed + offset, not dofs; the full model is then in NS::independent)");
  cmd->add_flag("--instantiate", o->instantiate,
                "also write NS/dynamics_double.cpp and NS/dynamics_float.cpp with every function instantiated, and declare "
                "them extern template in the header: the robot's code is compiled once, in those files (link them)");
  cmd->add_flag("--batch", o->batch,
                "also write NS/batch.hpp: the functions over N states at a time (row-major N x n arrays) on xsimd packs "
                "and threads (needs xsimd, libxsimd-dev); with --scene, the scene's functions (and its header gets forward_kinematics, "
                "jacobian and center_of_mass)");
  cmd->add_option("--depfile", o->depfile, "also write a Makefile-syntax depfile (header: inputs) for the build system");
  return {cmd,
          [o] {
            if(o->scene.empty() && o->robot.urdf.empty()) throw std::invalid_argument("generate: give a URDF or --scene");
            GenerateOptions opt;
            opt.urdf = o->robot.urdf;
            opt.scene = o->scene;
            opt.strict = o->strict;
            opt.derivatives = o->derivatives;
            opt.independentMimic = o->independentMimic;
            opt.instantiate = o->instantiate;
            opt.batch = o->batch;
            opt.floatingBase = o->robot.floatingBase;
            opt.baseLink = o->robot.baseLink;
            opt.outDir = o->outDir;
            opt.ns = o->ns;
            std::vector<std::string> inputs;
            const std::vector<GeneratedFile> files = generateFiles(opt, &inputs);
            const std::vector<std::string> written = writeFiles(o->outDir, files);
            if(!o->depfile.empty())
            {
              // The depfile names the header by the path given to the build system (absolute).
              const std::string target = std::filesystem::absolute(written.front()).lexically_normal().string();
              const std::string tmp = o->depfile + ".rbdgen-tmp";
              {
                std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
                out << depfileText(target, inputs);
                if(!out) throw std::runtime_error(o->depfile + ": cannot write file");
              }
              std::filesystem::rename(tmp, o->depfile);
            }
            for(const auto & path : written) std::cout << path << "\n";
            return 0;
          },
          [o] { return o->scene.empty() ? o->robot.urdf : o->scene; }};
}

} // namespace rbdgen::cli
