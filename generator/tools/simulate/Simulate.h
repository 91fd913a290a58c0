#pragma once
// `rbdgen simulate`: run a scene with the runtime (rbd::scene, double), write the trajectory as
// CSV and plot it with gnuplot (energy, joint positions, contact normal forces).

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <rbd/MultiBody.h>
#include <rbd/scene/Scene.h>

namespace rbdgen::simulate
{

struct SimulateOptions
{
  std::string scene;                          ///< scene file
  std::optional<double> duration, dt;         ///< override the scene's <simulation>
  std::optional<rbd::scene::Integrator> integrator;
  std::string csv;                            ///< default: <scene file stem>.csv
  std::string png;                            ///< default: the CSV path with .png; the .gp script beside the CSV
  bool plot = true;                           ///< false: CSV only
};

struct SimulateResult
{
  std::string csv, gp, png;  ///< files written (png empty if gnuplot could not make it)
  long steps = 0;
  std::size_t rows = 0;
  double energyStart = 0, energyEnd = 0; ///< total (kinetic + potential + contact) energy
  std::vector<std::string> warnings;
};

/// Parse an integrator name as in the scene file (semi_implicit_euler, explicit_euler, rk4).
rbd::scene::Integrator parseIntegrator(const std::string & name);

/// Run the scene; progress on `progress` (percent, see Simulate.cpp). Throws on any error, leaving
/// no output file behind.
SimulateResult runSimulation(const SimulateOptions & options, std::ostream & progress);

/// CSV column names: t, q_<joint>[_<k>]..., alpha_<joint>[_<k>]..., energies, fn_<contact>...
std::vector<std::string> csvHeader(const rbd::MultiBody & mb, const rbd::scene::Scene & scene);

/// The gnuplot script plotting csv into png (panels: energy, joint positions, contact forces).
std::string gnuplotScript(const std::string & csv, const std::string & png, const std::vector<std::string> & header,
                          const std::string & title);

} // namespace rbdgen::simulate
