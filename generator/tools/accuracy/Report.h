#pragma once
// The study's outputs, as text (nothing written here): accuracy.md, accuracy.csv and the gnuplot
// data and scripts of the two plots (error vs time per call, Pareto fronts marked; integrator error
// vs wall time per simulated second).

#include <map>
#include <optional>
#include <string>

#include "SimulationStudy.h"
#include "StaticStudy.h"

namespace rbdgen::accuracy
{

struct StudyInfo
{
  std::string robot;        ///< robot name
  std::string urdf;         ///< as given
  std::string options;      ///< command-line options that matter (base, scene)
  int nq = 0, nv = 0, states = 0;
  unsigned long long seed = 0;
  std::string compiler;     ///< driver compiler and flags
  double condHMedian = 0, condHMax = 0;
};

struct StudyResults
{
  StudyInfo info;
  std::vector<StaticRow> staticRows;
  std::optional<SimulationStudy> simulation;
};

/// file name -> content: accuracy.md, accuracy.csv, accuracy_static.{dat,gp},
/// accuracy_simulation.{dat,gp} (the latter only with a simulation study).
std::map<std::string, std::string> renderReport(const StudyResults & r);

/// PNG files the .gp scripts produce (to check after running gnuplot).
std::vector<std::string> plotImages(const StudyResults & r);

} // namespace rbdgen::accuracy
