// Quick start: the dynamics generated for one URDF (robot/dynamics.hpp, made at build time by
// generate_robot_dynamics) against the generic runtime loaded from the same URDF.
//  1. accuracy: for 1000 seeded random states, the largest relative error of the generated forward
//     kinematics, inverse dynamics, mass matrix and forward dynamics w.r.t. the runtime;
//  2. speed: time per call of inverse and forward dynamics, runtime vs generated (median of several
//     runs, each over a pool of pre-generated inputs, one different input per call).
// Exit status 1 if an error exceeds kTolerance (forward dynamics: kTolerance + cond(H) eps, checked
// only on states where cond(H) eps <= kMeaningful; an ill-conditioned robot's forward dynamics is
// reported as not verified). A header without forward dynamics (has_forward_dynamics == false:
// singular mass matrix) is checked for the rest, with a line saying why forward dynamics is skipped.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <robot/dynamics.hpp>

#include <Eigen/Eigenvalues>
#include <rbd/FD.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/parsers/urdf.h>

// model::forward_dynamics exists only when model::has_forward_dynamics. These declarations, never
// called, keep the code below well-formed for either header; the header's function wins overload
// resolution when it exists (both are seen through the using-directives of quickstart_fd).
/// The full model (mimic joints as dofs; the same as robot:: without mimic joints): the runtime's tree.
namespace model = robot::independent;

namespace quickstart_fallback
{
struct Absent
{
};
template<class S, class... A> Absent forward_dynamics(const A &...);
} // namespace quickstart_fallback
namespace quickstart_fd
{
using namespace quickstart_fallback;
using namespace robot::independent;
} // namespace quickstart_fd

namespace
{

using VectorX = Eigen::VectorXd;
constexpr int kStates = 1000;      // random states for the accuracy check, and the timing pool
constexpr int kRuns = 9;           // timing: median of kRuns runs over the whole pool
constexpr double kTolerance = 1e-9;
constexpr double kMeaningful = 1e-6; // forward dynamics is checked where cond(H) eps <= kMeaningful

/// Generated forward dynamics alphaD = FD(q, alpha, tau) (zero when the header has none; never
/// called then). A template, so that the call is compiled only when it exists.
template<class S = double>
model::Tangent<S> generatedForwardDynamics(const VectorX & q, const VectorX & alpha, const VectorX & tau)
{
  if constexpr(model::has_forward_dynamics)
    return quickstart_fd::forward_dynamics<S>(model::Config<S>(q), model::Tangent<S>(alpha), model::Tangent<S>(tau));
  else return model::Tangent<S>::Zero();
}


/// Keep `p` and what it points to alive: the compiler must assume the asm reads it.
template<class T>
inline void keep(const T & value)
{
  asm volatile("" : : "g"(&value) : "memory");
}

/// Relative error ||a - b||_inf / ||b||_inf (absolute when b = 0).
template<class A, class B>
double relErr(const Eigen::MatrixBase<A> & a, const Eigen::MatrixBase<B> & b)
{
  const double scale = b.template lpNorm<Eigen::Infinity>();
  const double diff = (a - b).template lpNorm<Eigen::Infinity>();
  return scale > 0 ? diff / scale : diff;
}

struct State
{
  VectorX q, alpha, alphaD, tau;
};

/// Uniform joint values in [-3, 3] (unit quaternions for spherical and free joints), velocities,
/// accelerations and torques in [-2, 2].
State randomState(std::mt19937 & rng, const rbd::MultiBody & mb)
{
  std::uniform_real_distribution<double> u(-1, 1);
  State s{VectorX(mb.nrParams()), VectorX(mb.nrDof()), VectorX(mb.nrDof()), VectorX(mb.nrDof())};
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto & j = mb.joint(i);
    const int p = mb.jointPosInParam(i);
    for(int k = 0; k < j.params(); ++k) s.q(p + k) = 3 * u(rng);
    if(j.type() == rbd::Joint::Spherical || j.type() == rbd::Joint::Free)
    {
      Eigen::Vector4d quat(u(rng), u(rng), u(rng), u(rng));
      s.q.segment<4>(p) = quat.normalized();
    }
  }
  for(int k = 0; k < mb.nrDof(); ++k)
  {
    s.alpha(k) = 2 * u(rng);
    s.alphaD(k) = 2 * u(rng);
    s.tau(k) = 2 * u(rng);
  }
  return s;
}

/// The runtime's path from flat vectors: q, alpha (+ alphaD or tau) -> mbc -> FK, FV.
void setState(const rbd::MultiBody & mb, rbd::MultiBodyConfig & mbc, const State & s)
{
  rbd::vectorToParam<double>(s.q, mbc.q);
  rbd::vectorToDof<double>(s.alpha, mbc.alpha);
  rbd::vectorToDof<double>(s.alphaD, mbc.alphaD);
  rbd::vectorToDof<double>(s.tau, mbc.jointTorque);
  rbd::forwardKinematics(mb, mbc);
  rbd::forwardVelocity(mb, mbc);
}

/// Median over kRuns of the time per call of f(state) over the pool, in ns.
template<class F>
double nsPerCall(const std::vector<State> & pool, F && f)
{
  std::vector<double> runs;
  for(int r = 0; r < kRuns; ++r)
  {
    const auto t0 = std::chrono::steady_clock::now();
    for(const State & s : pool) f(s);
    const auto t1 = std::chrono::steady_clock::now();
    runs.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / static_cast<double>(pool.size()));
  }
  std::nth_element(runs.begin(), runs.begin() + kRuns / 2, runs.end());
  return runs[kRuns / 2];
}

} // namespace

int main()
{
  rbd::parsers::ParserOptions opt;
  opt.fixed = !RBDGEN_QUICKSTART_FLOATING_BASE;
  const rbd::parsers::ParserResult urdf = rbd::parsers::fromUrdfFile(RBDGEN_QUICKSTART_URDF_PATH, opt);
  const rbd::MultiBody & mb = urdf.mb;
  std::printf("robot '%s' from %s (%s base): nq = %d, nv = %d, %d bodies\n", urdf.name.c_str(),
              RBDGEN_QUICKSTART_URDF_PATH, RBDGEN_QUICKSTART_FLOATING_BASE ? "floating" : "fixed", model::nq, model::nv,
              model::nbodies);
  if(mb.nrParams() != model::nq || mb.nrDof() != model::nv || mb.nrBodies() != model::nbodies)
  {
    std::printf("error: the generated header does not match the URDF (nq %d, nv %d, bodies %d)\n", mb.nrParams(),
                mb.nrDof(), mb.nrBodies());
    return 1;
  }
  if(mb.nrDof() != robot::nv) // mb is the full model (== model::nv, checked above)
    std::printf("mimic joints coupled: robot:: has nq = %d, nv = %d; the checks below are on the full model "
                "robot::independent (the coupled functions are its projection, tests/generator/test_mimic_coupling)\n",
                robot::nq, robot::nv);
  // MultiBody body frame -> URDF link frame (identity unless the base is not the URDF root).
  std::vector<sva::PTransformd> X_mb_link;
  for(const auto & b : mb.bodies())
  {
    const auto it = urdf.bodyBaseTransforms.find(b.name());
    X_mb_link.push_back(it == urdf.bodyBaseTransforms.end() ? sva::PTransformd::Identity() : it->second.inv());
  }

  std::mt19937 rng(2024);
  std::vector<State> pool;
  for(int s = 0; s < kStates; ++s) pool.push_back(randomState(rng, mb));

  // --- 1. accuracy --------------------------------------------------------------------------
  rbd::MultiBodyConfig mbc(mb);
  rbd::InverseDynamics id(mb);
  rbd::ForwardDynamics fd(mb);
  double errFK = 0, errID = 0, errH = 0, errFD = 0, worstCondH = 0, bestCondH = HUGE_VAL;
  bool fdWithinBound = true;
  int fdChecked = 0; // states where cond(H) eps <= kMeaningful
  const double eps = std::numeric_limits<double>::epsilon();
  for(const State & s : pool)
  {
    const model::Config<double> q = s.q;
    const model::Tangent<double> alpha = s.alpha, alphaD = s.alphaD;
    setState(mb, mbc, s);
    // Forward kinematics: world pose of every link.
    const auto poses = model::forward_kinematics<double>(q);
    for(int i = 0; i < mb.nrBodies(); ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      const sva::PTransformd X_0_link = X_mb_link[k] * mbc.bodyPosW[k];
      errFK = std::max({errFK, relErr(poses[k].rotation, X_0_link.rotation()),
                        relErr(poses[k].translation, X_0_link.translation())});
    }
    // Inverse dynamics: tau = ID(q, alpha, alphaD).
    id.inverseDynamics(mb, mbc);
    errID = std::max(errID, relErr(model::inverse_dynamics<double>(q, alpha, alphaD), rbd::dofToVector(mb, mbc.jointTorque)));
    // Mass matrix and forward dynamics: alphaD = H^-1 (tau - C).
    rbd::vectorToDof<double>(s.tau, mbc.jointTorque);
    fd.forwardDynamics(mb, mbc);
    errH = std::max(errH, relErr(model::mass_matrix<double>(q), fd.H()));
    // An ill-conditioned H amplifies rounding: both solves are only good to about cond(H) eps, so
    // the comparison means something only where cond(H) eps is small.
    const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(fd.H(), Eigen::EigenvaluesOnly).eigenvalues();
    const double condH = lambda.minCoeff() > 0 ? lambda.maxCoeff() / lambda.minCoeff() : HUGE_VAL; // singular H
    worstCondH = std::max(worstCondH, condH);
    bestCondH = std::min(bestCondH, condH);
    if(model::has_forward_dynamics && condH * eps <= kMeaningful)
    {
      const double eFD = relErr(generatedForwardDynamics(s.q, s.alpha, s.tau), rbd::dofToVector(mb, mbc.alphaD));
      errFD = std::max(errFD, eFD);
      fdWithinBound = fdWithinBound && eFD <= kTolerance + condH * eps;
      ++fdChecked;
    }
  }
  std::printf("\naccuracy over %d random states: max relative error ||generated - runtime||inf / ||runtime||inf\n",
              kStates);
  const bool okFK = errFK <= kTolerance, okID = errID <= kTolerance, okH = errH <= kTolerance;
  std::printf("  %-20s %9.2e  %s\n", "forward kinematics", errFK, okFK ? "ok" : "MISMATCH");
  std::printf("  %-20s %9.2e  %s\n", "inverse dynamics", errID, okID ? "ok" : "MISMATCH");
  std::printf("  %-20s %9.2e  %s\n", "mass matrix", errH, okH ? "ok" : "MISMATCH");
  if(!model::has_forward_dynamics)
    std::printf("  %-20s %9s  skipped: the header has no forward dynamics (has_forward_dynamics == false: the mass "
                "matrix is singular; rbdgen's warning and the header's comment name the joints)\n",
                "forward dynamics", "-");
  else if(fdChecked == 0)
    std::printf("  %-20s %9s  NOT VERIFIED: ill-conditioned mass matrix, cond(H) >= %.1e on every state (cond(H) eps "
                "> %.0e: neither solver is meaningful; see rbdgen's warnings)\n",
                "forward dynamics", "-", bestCondH, kMeaningful);
  else
    std::printf("  %-20s %9.2e  %s (%d of %d states with cond(H) eps <= %.0e; largest cond(H) %.1e; bound per state: "
                "%.0e + cond(H) eps)\n",
                "forward dynamics", errFD, fdWithinBound ? "ok" : "MISMATCH", fdChecked, kStates, kMeaningful, worstCondH,
                kTolerance);
  const bool ok = okFK && okID && okH && fdWithinBound;

  // --- 2. speed -----------------------------------------------------------------------------
  const double rtID = nsPerCall(pool, [&](const State & s) {
    setState(mb, mbc, s);
    id.inverseDynamics(mb, mbc);
    keep(mbc.jointTorque[0]);
  });
  const double genID = nsPerCall(pool, [&](const State & s) {
    const model::Tangent<double> t = model::inverse_dynamics<double>(model::Config<double>(s.q), s.alpha, s.alphaD);
    keep(t);
  });
  const double rtFD = nsPerCall(pool, [&](const State & s) {
    setState(mb, mbc, s);
    fd.forwardDynamics(mb, mbc);
    keep(mbc.alphaD[0]);
  });
  double genFD = 0;
  if(model::has_forward_dynamics)
    genFD = nsPerCall(pool, [&](const State & s) {
      const model::Tangent<double> a = generatedForwardDynamics(s.q, s.alpha, s.tau);
      keep(a);
    });
  std::printf("\ntime per call, ns (median of %d runs over %d different inputs; runtime = set mbc + FK + FV + algorithm)\n",
              kRuns, kStates);
  std::printf("  %-20s %10s %10s %9s\n", "", "runtime", "generated", "speed-up");
  std::printf("  %-20s %10.0f %10.0f %8.1fx\n", "inverse dynamics", rtID, genID, rtID / genID);
  if(model::has_forward_dynamics) std::printf("  %-20s %10.0f %10.0f %8.1fx\n", "forward dynamics", rtFD, genFD, rtFD / genFD);
  else std::printf("  %-20s %10.0f %10s %9s  (not generated: singular mass matrix)\n", "forward dynamics", rtFD, "-", "-");
  return ok ? 0 : 1;
}
