// `rbdgen info ROBOT.urdf`: the kinematic tree, masses, warnings and gravity torques.
#include <iostream>
#include <memory>

#include "../info.h"
#include "Command.h"
#include "RobotOptions.h"

namespace rbdgen::cli
{

Command addInfoCommand(CLI::App & app)
{
  auto robot = std::make_shared<RobotOptions>();
  CLI::App * cmd = app.add_subcommand("info", "print the kinematic tree, masses, warnings and gravity torques");
  robot->addTo(*cmd);
  return {cmd,
          [robot] {
            printInfo(std::cout, robot->load(), robot->urdf);
            return 0;
          },
          [robot] { return robot->urdf; }};
}

} // namespace rbdgen::cli
