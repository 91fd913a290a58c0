#include "SimulationStudy.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include <rbd/scene/Controller.h>
#include <rbd/scene/Integrators.h>
#include <rbd/scene/SceneDynamics.h>
#include <rbd/scene/SceneLoader.h>

#include "ErrorStats.h"
#include "Pareto.h"

namespace rbdgen::accuracy
{

using rbd::scene::Integrator;

std::string integratorName(Integrator integrator)
{
  switch(integrator)
  {
    case Integrator::SemiImplicitEuler:
      return "semi_implicit_euler";
    case Integrator::ExplicitEuler:
      return "explicit_euler";
    case Integrator::RK4:
      return "rk4";
  }
  return "?";
}

std::vector<double> observedOrders(const std::vector<double> & dts, const std::vector<double> & errors)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> p(errors.size(), nan);
  for(std::size_t i = 1; i < errors.size(); ++i)
  {
    const double e0 = errors[i - 1], e1 = errors[i];
    if(e0 > 0 && e1 > 0 && std::isfinite(e0) && std::isfinite(e1))
      p[i] = std::log(e0 / e1) / std::log(dts[i - 1] / dts[i]);
  }
  return p;
}

namespace
{

template<class T>
using Vec = Eigen::Matrix<T, Eigen::Dynamic, 1>;

/// One integration of the scene over the horizon; energies at every multiple of sampleDt.
template<class T>
struct Run
{
  rbd::scene::SceneState<T> final;
  std::vector<double> energy; ///< at t = 0, sampleDt, 2 sampleDt, ... (stops early if diverged)
  double seconds = 0;         ///< wall time spent in step()
  bool diverged = false;
};

template<class T>
T energyOf(const rbd::scene::SceneDynamicsTpl<T> & dyn, const rbd::scene::SceneState<T> & s)
{
  return dyn.kineticEnergy(s.q, s.alpha) + dyn.potentialEnergy(s.q) + dyn.contactEnergy(s.q);
}

/// Number of steps of size dt in a span, checked to be an integer.
long stepsIn(double span, double dt)
{
  const double n = span / dt;
  const long k = std::lround(n);
  if(k < 1 || std::abs(n - static_cast<double>(k)) > 1e-6 * n)
    throw std::runtime_error("step " + std::to_string(dt) + " s does not divide " + std::to_string(span) + " s");
  return k;
}

template<class T>
Run<T> integrate(const rbd::scene::SceneDynamicsTpl<T> & dyn, const rbd::scene::SceneControllerTpl<T> & ctrl,
                 rbd::scene::SceneState<T> s, Integrator integrator, double dt, const SimulationOptions & opt)
{
  Run<T> run;
  const long perSample = stepsIn(opt.sampleDt, dt), samples = stepsIn(opt.horizon, opt.sampleDt);
  run.energy.push_back(static_cast<double>(energyOf(dyn, s)));
  using Clock = std::chrono::steady_clock;
  for(long k = 0; k < samples && !run.diverged; ++k)
  {
    const auto t0 = Clock::now();
    for(long i = 0; i < perSample; ++i)
    {
      const Vec<T> tau = ctrl.torque(s.q, s.alpha);
      try
      {
        rbd::scene::step(dyn, s, tau, T(dt), integrator);
      }
      catch(const std::runtime_error &) // the runtime throws on a non-finite acceleration
      {
        run.diverged = true;
        break;
      }
      if(!s.q.allFinite() || !s.alpha.allFinite())
      {
        run.diverged = true;
        break;
      }
    }
    run.seconds += std::chrono::duration<double>(Clock::now() - t0).count();
    if(!run.diverged) run.energy.push_back(static_cast<double>(energyOf(dyn, s)));
  }
  run.final = s;
  return run;
}

/// The initial state: the scene's (<initial>, default zero), or seeded random joint positions
/// in [-1, 1] rad (m) and velocities in [-1, 1], the free base at rest at the origin.
rbd::scene::SceneState<double> initialStateFor(const rbd::scene::SceneDynamics & dyn, const SimulationOptions & opt,
                                               std::string & note)
{
  rbd::scene::SceneState<double> s = rbd::scene::initialState(dyn);
  if(!opt.randomInitialState)
  {
    note = "initial state from the scene";
    return s;
  }
  std::mt19937_64 rng(opt.seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto & mb = dyn.mb();
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto & j = mb.joint(i);
    if(j.type() == rbd::JointType::Free || j.type() == rbd::JointType::Spherical) continue;
    for(int k = 0; k < j.params(); ++k) s.q(mb.jointPosInParam(i) + k) = u(rng);
    for(int k = 0; k < j.dof(); ++k) s.alpha(mb.jointPosInDof(i) + k) = u(rng);
  }
  note = "seeded random initial joint positions and velocities in [-1, 1] (seed " + std::to_string(opt.seed) + ")";
  return s;
}

} // namespace

SimulationStudy runSimulationStudy(const rbd::scene::Scene & scene, const SimulationOptions & opt)
{
  using LD = long double;
  const rbd::scene::SceneRobot robot = rbd::scene::loadSceneRobot(scene);
  const rbd::scene::SceneDynamics dyn(robot, scene);
  const rbd::scene::SceneDynamicsTpl<LD> dynL(robot, scene);
  SimulationStudy study;
  study.horizon = opt.horizon;
  const rbd::scene::SceneState<double> x0 = initialStateFor(dyn, opt, study.initialStateNote);
  const rbd::scene::SceneState<LD> x0L{x0.q.cast<LD>(), x0.alpha.cast<LD>()};
  const rbd::scene::SceneController ctrl(dyn, x0);
  const rbd::scene::SceneControllerTpl<LD> ctrlL(dynL, x0L);

  // Reference: long double RK4 at referenceDt, and at 2 referenceDt for its own error (RK4: e(2h) - e(h) ~ 15 e(h)).
  study.referenceDt = opt.referenceDt;
  const Run<LD> ref = integrate(dynL, ctrlL, x0L, Integrator::RK4, opt.referenceDt, opt);
  const Run<LD> ref2 = integrate(dynL, ctrlL, x0L, Integrator::RK4, 2 * opt.referenceDt, opt);
  if(ref.diverged) throw std::runtime_error("the long double reference trajectory diverged");
  const Eigen::VectorXd qRef = ref.final.q.cast<double>(), alphaRef = ref.final.alpha.cast<double>();
  study.referenceError = relativeError(ref2.final.q.cast<double>(), qRef) / 15;
  study.initialEnergy = ref.energy.front();
  study.referenceEnergyDrift = std::abs(ref.energy.back() - ref.energy.front());

  for(Integrator integrator : {Integrator::SemiImplicitEuler, Integrator::ExplicitEuler, Integrator::RK4})
  {
    std::vector<double> errors;
    const std::size_t first = study.rows.size();
    for(double dt : opt.dts)
    {
      // Errors from the first run; wall time: median over 3 to 9 runs (at least 50 ms in all).
      const Run<double> run = integrate(dyn, ctrl, x0, integrator, dt, opt);
      std::vector<double> seconds = {run.seconds};
      double total = run.seconds;
      while(seconds.size() < 3 || (total < 0.05 && seconds.size() < 9))
      {
        seconds.push_back(integrate(dyn, ctrl, x0, integrator, dt, opt).seconds);
        total += seconds.back();
      }
      std::nth_element(seconds.begin(), seconds.begin() + static_cast<long>(seconds.size() / 2), seconds.end());
      SimulationRow row;
      row.integrator = integratorName(integrator);
      row.dt = dt;
      row.wallPerSimSecond = seconds[seconds.size() / 2] / opt.horizon;
      row.diverged = run.diverged;
      const double inf = std::numeric_limits<double>::infinity();
      row.trajectoryError = run.diverged ? inf : relativeError(run.final.q, qRef);
      row.velocityError = run.diverged ? inf : relativeError(run.final.alpha, alphaRef);
      row.energyError = run.diverged ? inf : 0.0;
      for(std::size_t k = 0; !run.diverged && k < run.energy.size() && k < ref.energy.size(); ++k)
        row.energyError = std::max(row.energyError, std::abs(run.energy[k] - ref.energy[k]));
      errors.push_back(row.trajectoryError);
      study.rows.push_back(row);
    }
    const std::vector<double> orders = observedOrders(opt.dts, errors);
    for(std::size_t k = 0; k < orders.size(); ++k) study.rows[first + k].observedOrder = orders[k];
  }
  std::vector<CostError> pts;
  for(const SimulationRow & r : study.rows) pts.push_back({r.wallPerSimSecond, r.trajectoryError});
  const std::vector<bool> front = paretoFront(pts);
  for(std::size_t k = 0; k < front.size(); ++k) study.rows[k].pareto = front[k];
  return study;
}

} // namespace rbdgen::accuracy
