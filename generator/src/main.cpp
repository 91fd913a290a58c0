// rbdgen command line: `rbdgen generate ROBOT.urdf --out DIR`, `rbdgen info ROBOT.urdf`.
// Exit code 0 only on success; every error is one line on stderr ("rbdgen: error: <file>: ...")
// and leaves no partial output.
#include <algorithm>
#include <iostream>
#include <set>

#include <CLI/CLI.hpp>

#include <rbd/parsers/urdf.h>

#include "Generate.h"
#include "info.h"

namespace
{

struct RobotOptions
{
  std::string urdf;
  bool floatingBase = false;
  std::string baseLink;

  void addTo(CLI::App & cmd)
  {
    cmd.add_option("urdf", urdf, "URDF file of the robot")->required()->check(CLI::ExistingFile);
    cmd.add_flag("--floating-base", floatingBase, "attach the base link to the world by a free joint");
    cmd.add_option("--base-link", baseLink, "link to use as the base (default: the URDF root)");
  }

  rbd::parsers::ParserResult load() const
  {
    rbd::parsers::ParserOptions opt;
    opt.fixed = !floatingBase;
    opt.baseLink = baseLink;
    return rbd::parsers::fromUrdfFile(urdf, opt);
  }
};

/// "rbdgen: error: <message>" on one line (newlines in the message become spaces).
std::string errorLine(std::string message)
{
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::replace(message.begin(), message.end(), '\r', ' ');
  return "rbdgen: error: " + message + "\n";
}

} // namespace

int main(int argc, char ** argv)
{
  CLI::App app{"rbdgen: a compiler for robot dynamics (URDF -> unrolled C++)"};
  // Before the subcommands are added: they copy it. One line, as every other error.
  app.failure_message(
      [](const CLI::App *, const CLI::Error & e) { return errorLine(std::string(e.what()) + " (see rbdgen --help)"); });
  app.set_version_flag("--version", std::string("rbdgen ") + RBDGEN_VERSION);
  app.require_subcommand(1);

  RobotOptions infoRobot;
  CLI::App * info = app.add_subcommand("info", "print the kinematic tree, masses, warnings and gravity torques");
  infoRobot.addTo(*info);

  RobotOptions genRobot;
  std::string outDir, ns;
  CLI::App * gen = app.add_subcommand("generate", "emit NS/dynamics.hpp for the robot into --out DIR");
  genRobot.addTo(*gen);
  gen->add_option("--out", outDir, "output directory")->required();
  gen->add_option("--namespace", ns, "C++ namespace (default: the robot name, sanitised)");

  try
  {
    app.parse(argc, argv);
  }
  catch(const CLI::ParseError & e)
  {
    return app.exit(e);
  }

  const std::string & urdf = info->parsed() ? infoRobot.urdf : genRobot.urdf;
  try
  {
    if(info->parsed()) rbdgen::printInfo(std::cout, infoRobot.load());
    if(gen->parsed())
    {
      rbdgen::GenerateOptions opt;
      opt.urdf = genRobot.urdf;
      opt.floatingBase = genRobot.floatingBase;
      opt.baseLink = genRobot.baseLink;
      opt.outDir = outDir;
      opt.ns = ns;
      for(const auto & path : rbdgen::writeFiles(outDir, rbdgen::generateFiles(opt))) std::cout << path << "\n";
    }
  }
  catch(const rbd::parsers::UrdfError & e)
  {
    std::cerr << errorLine(e.what()); // already "<file>: <element> '<name>': <reason>"
    return 1;
  }
  catch(const std::exception & e)
  {
    std::cerr << errorLine(urdf + ": " + e.what()); // namespace, output directory...
    return 1;
  }
  return 0;
}
