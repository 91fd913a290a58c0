#pragma once
// The robot options shared by subcommands: URDF, fixed or floating base, base link.
#include <string>

#include <CLI/CLI.hpp>

#include <rbd/parsers/urdf.h>

namespace rbdgen::cli
{

struct RobotOptions
{
  std::string urdf;
  bool floatingBase = false;
  std::string baseLink;

  /// required: the URDF positional argument must be given.
  void addTo(CLI::App & cmd, bool required = true)
  {
    auto * opt = cmd.add_option("urdf", urdf, "URDF file of the robot")->check(CLI::ExistingFile);
    if(required) opt->required();
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

} // namespace rbdgen::cli
