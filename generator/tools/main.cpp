// rbdgen command line: `rbdgen <subcommand> ...`; each subcommand lives in cli/<Name>Command.cpp.
// Exit code 0 only on success; every error is one line on stderr ("rbdgen: error: <file>: ...")
// and leaves no partial output.
#include <algorithm>
#include <iostream>
#include <vector>

#include <CLI/CLI.hpp>

#include <rbd/parsers/urdf.h>

#include "cli/Command.h"

namespace
{

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

  using namespace rbdgen::cli;
  const std::vector<Command> commands = {
      addInfoCommand(app),
      addGenerateCommand(app),
      addSimulateCommand(app),
      addAccuracyCommand(app),
  };

  try
  {
    app.parse(argc, argv);
  }
  catch(const CLI::ParseError & e)
  {
    return app.exit(e);
  }

  for(const Command & c : commands)
  {
    if(!c.app->parsed()) continue;
    try
    {
      return c.run();
    }
    catch(const rbd::parsers::UrdfError & e)
    {
      std::cerr << errorLine(e.what()); // already "<file>: <element> '<name>': <reason>"
    }
    catch(const std::exception & e)
    {
      // Errors that already name their file (scene errors...) start with it; others get the input.
      const std::string input = c.input ? c.input() : std::string();
      const std::string what = e.what();
      const bool named = !input.empty() && what.rfind(input, 0) == 0;
      std::cerr << errorLine(input.empty() || named ? what : input + ": " + what);
    }
    return 1;
  }
  return 1;
}
