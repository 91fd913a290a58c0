#pragma once
// One `rbdgen` subcommand: it registers its options on the application and, when the user chose
// it, runs. run() returns the exit code and throws on error (main prints one line and exits 1).
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace rbdgen::cli
{

struct Command
{
  CLI::App * app = nullptr;       ///< the subcommand (parsed() tells whether the user chose it)
  std::function<int()> run;       ///< executes it; returns the exit code
  std::function<std::string()> input; ///< the input file named in error messages ("" if none)
};

/// Each subcommand lives in its own file (cli/<name>.cpp) and provides one of these.
Command addInfoCommand(CLI::App & app);
Command addGenerateCommand(CLI::App & app);
Command addSimulateCommand(CLI::App & app);
Command addAccuracyCommand(CLI::App & app);

} // namespace rbdgen::cli
