#pragma once
// The simulation part of the study: the runtime scene dynamics in double, integrated from the same
// initial state over a fixed horizon by each integrator at each step size, against a reference
// trajectory (the same scene in long double, RK4 with a small step).
//   trajectory error = ||q(T) - q_ref(T)||_inf / max(1, ||q_ref(T)||_inf)  (relativeError)
//   velocity error   = the same for alpha
//   energy error     = max over sample times t (every sampleDt) of |E(t) - E_ref(t)| (J), E the
//                      scene's kinetic + potential (+ contact) energy
//   wall time per simulated second = time spent in step() / horizon
//   observed order   = log(e(dt1)/e(dt2)) / log(dt1/dt2) between consecutive step sizes

#include <cstdint>
#include <string>
#include <vector>

#include <rbd/scene/Scene.h>

namespace rbdgen::accuracy
{

struct SimulationOptions
{
  double horizon = 1.0;   ///< s
  std::vector<double> dts = {1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4}; ///< each must divide sampleDt
  double sampleDt = 1e-2; ///< energy sampling period, s
  double referenceDt = 2.5e-5;
  bool randomInitialState = false; ///< seeded random joint state instead of the scene's initial state
  std::uint64_t seed = 1;
};

struct SimulationRow
{
  std::string integrator;   ///< semi_implicit_euler, explicit_euler, rk4
  double dt = 0;
  double wallPerSimSecond = 0; ///< s of wall time per simulated s
  double trajectoryError = 0, velocityError = 0, energyError = 0;
  double observedOrder = 0;    ///< against the previous (larger) step of the same integrator; NaN for the first
  bool diverged = false;       ///< a non-finite state was reached
  bool pareto = false;         ///< on the front of (wall per sim s, trajectory error) over all rows
};

struct SimulationStudy
{
  std::vector<SimulationRow> rows;
  double horizon = 0;        ///< s
  double referenceDt = 0;
  double referenceError = 0; ///< ||q_ref(dt) - q_ref(2 dt)||_inf / 15: estimate of the reference's own error
  double referenceEnergyDrift = 0; ///< |E_ref(T) - E_ref(0)| (J); 0 up to the reference error if conservative
  double initialEnergy = 0;
  std::string initialStateNote; ///< where the initial state came from
};

/// Integrator name as in scene files.
std::string integratorName(rbd::scene::Integrator integrator);

/// Run the study on the scene (tau from the scene's controller).
SimulationStudy runSimulationStudy(const rbd::scene::Scene & scene, const SimulationOptions & opt);

/// Observed orders of convergence for errors at decreasing steps: out[0] = NaN,
/// out[i] = log(e[i-1]/e[i]) / log(dt[i-1]/dt[i]) (NaN when an error is 0 or not finite).
std::vector<double> observedOrders(const std::vector<double> & dts, const std::vector<double> & errors);

} // namespace rbdgen::accuracy
