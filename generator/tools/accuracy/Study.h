#pragma once
// `rbdgen accuracy`: the whole study for one robot (static variants, simulation), written to DIR.

#include <cstdint>
#include <string>
#include <vector>

#include "SimulationStudy.h"

namespace rbdgen::accuracy
{

struct StudyOptions
{
  std::string urdf;           ///< robot (ignored when scene is set: the scene names its robot)
  bool floatingBase = false;
  std::string baseLink;
  std::string scene;          ///< scene file (optional): robot, effects and initial state of the simulation
  std::string outDir;
  int states = 1000;
  std::uint64_t seed = 1;
  std::string cxx;            ///< driver compiler (empty: $CXX, else rbdgen's)
  bool simulation = true;     ///< run the integrator study
  bool plots = true;          ///< run gnuplot
  bool derivatives = true;    ///< also study inverse / forward dynamics derivatives
  SimulationOptions sim;
};

/// Run the study and write DIR/accuracy.{md,csv}, the plot data, scripts and PNGs (only once
/// everything succeeded). Returns the paths written. Throws std::runtime_error on error.
std::vector<std::string> runStudy(const StudyOptions & opt);

/// Throws unless dir exists as a writable directory or can be created (checked before the study).
void checkOutputDirectory(const std::string & dir);

} // namespace rbdgen::accuracy
