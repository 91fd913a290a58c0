// `rbdgen generate ROBOT.urdf --out DIR`: emit NS/dynamics.hpp.
#include <iostream>
#include <memory>

#include "../Generate.h"
#include "Command.h"
#include "RobotOptions.h"

namespace rbdgen::cli
{

Command addGenerateCommand(CLI::App & app)
{
  struct Options
  {
    RobotOptions robot;
    std::string outDir, ns;
  };
  auto o = std::make_shared<Options>();
  CLI::App * cmd = app.add_subcommand("generate", "emit NS/dynamics.hpp for the robot into --out DIR");
  o->robot.addTo(*cmd);
  cmd->add_option("--out", o->outDir, "output directory")->required();
  cmd->add_option("--namespace", o->ns, "C++ namespace (default: the robot name, sanitised)");
  return {cmd,
          [o] {
            GenerateOptions opt;
            opt.urdf = o->robot.urdf;
            opt.floatingBase = o->robot.floatingBase;
            opt.baseLink = o->robot.baseLink;
            opt.outDir = o->outDir;
            opt.ns = o->ns;
            for(const auto & path : writeFiles(o->outDir, generateFiles(opt))) std::cout << path << "\n";
            return 0;
          },
          [o] { return o->robot.urdf; }};
}

} // namespace rbdgen::cli
