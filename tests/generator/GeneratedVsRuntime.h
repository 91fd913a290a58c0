#pragma once
// Every generated function against the runtime on seeded random states, in double (relative error
// <= 1e-12, relative to max(1, |reference|)) and float (bounds below), plus zero allocations.
// A robot test file defines a traits struct R (see generated_test.cpp.in) and calls
// RBDGEN_GENERATED_TESTS(name, R).

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <rbd/CoM.h>
#include <rbd/FD.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/Jacobian.h>
#include <rbd/parsers/urdf.h>

#include "AllocationCounter.h"
#include "TestModels.h"

namespace rbdgentest
{

constexpr int kStates = 100;
constexpr double kTolDouble = 1e-12;
// float: ~2^-24 = 6e-8 per operation, grown by the length of the recursion and the magnitudes.
constexpr double kTolFloatKinematics = 2e-5;
constexpr double kTolFloatDynamics = 2e-4;

/// The runtime model of the same URDF, with the link frames the generated code reports.
template<class R>
struct Reference
{
  rbd::parsers::ParserResult robot;
  std::vector<sva::PTransformd> X_mb_link; // MultiBody body frame -> URDF link frame
  rbd::MultiBodyConfig mbc;

  Reference()
  {
    rbd::parsers::ParserOptions opt;
    opt.fixed = !R::floatingBase;
    robot = rbd::parsers::fromUrdfFile(R::urdf, opt);
    for(const auto & b : robot.mb.bodies())
    {
      const auto it = robot.bodyBaseTransforms.find(b.name());
      X_mb_link.push_back(it == robot.bodyBaseTransforms.end() ? sva::PTransformd::Identity() : it->second.inv());
    }
    mbc = rbd::MultiBodyConfig(robot.mb);
  }
  const rbd::MultiBody & mb() const { return robot.mb; }

  /// Random state (unit quaternions), kinematics and velocities computed.
  void sample(rbdtest::Rng & rng)
  {
    rbdtest::randomState(rng, mb(), mbc);
    rbd::forwardKinematics(mb(), mbc);
    rbd::forwardVelocity(mb(), mbc);
  }
  typename R::template Config<double> q() const { return rbd::paramToVector(mb(), mbc.q); }
  typename R::template Tangent<double> alpha() const { return rbd::dofToVector(mb(), mbc.alpha); }
  typename R::template Tangent<double> alphaD() const { return rbd::dofToVector(mb(), mbc.alphaD); }
  typename R::template Tangent<double> torque() const { return rbd::dofToVector(mb(), mbc.jointTorque); }

  /// Runtime inverse dynamics with the given terms.
  Eigen::VectorXd id(bool velocity, bool acceleration, bool gravity)
  {
    rbd::MultiBodyConfig c = mbc;
    if(!velocity)
      for(auto & a : c.alpha) std::fill(a.begin(), a.end(), 0.0);
    if(!acceleration)
      for(auto & a : c.alphaD) std::fill(a.begin(), a.end(), 0.0);
    if(!gravity) c.gravity.setZero();
    rbd::forwardVelocity(mb(), c);
    rbd::InverseDynamics idr(mb());
    idr.inverseDynamics(mb(), c);
    return rbd::dofToVector(mb(), c.jointTorque);
  }
};

template<class A, class B>
double err(const A & a, const B & b)
{
  return rbdtest::relErr(a, b);
}

// Compares with the double tolerance and the float one, records the worst errors seen.
struct ErrorLog
{
  double worstDouble = 0, worstFloat = 0;
  void add(double ed, double ef)
  {
    worstDouble = std::max(worstDouble, ed);
    worstFloat = std::max(worstFloat, ef);
  }
  void report(const char * what) const
  {
    std::printf("[ %s ] worst relative error: double %.3g, float %.3g\n", what, worstDouble, worstFloat);
  }
};

template<class R>
void checkForwardKinematics()
{
  Reference<R> ref;
  rbdtest::Rng rng(1);
  ErrorLog log;
  for(int s = 0; s < kStates; ++s)
  {
    ref.sample(rng);
    const auto q = ref.q();
    const auto poses = R::fk(q);
    const auto posesF = R::fk(typename R::template Config<float>(q.template cast<float>()));
    const auto kin = R::kinematics(q);
    for(int i = 0; i < R::nbodies; ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      const sva::PTransformd X = ref.X_mb_link[k] * ref.mbc.bodyPosW[k];
      const double ed = std::max(err(poses[k].rotation, X.rotation()), err(poses[k].translation, X.translation()));
      const double ef = std::max(err(posesF[k].rotation, X.rotation()), err(posesF[k].translation, X.translation()));
      ASSERT_LE(ed, kTolDouble) << "link " << R::bodyNames()[k];
      ASSERT_LE(ef, kTolFloatKinematics) << "link " << R::bodyNames()[k];
      ASSERT_EQ(kin.pose[k].rotation, poses[k].rotation);
      ASSERT_EQ(kin.pose[k].translation, poses[k].translation);
      log.add(ed, ef);
    }
  }
  log.report("forward_kinematics");
}

template<class R>
void checkInverseDynamics()
{
  Reference<R> ref;
  rbdtest::Rng rng(2);
  ErrorLog idLog, nleLog, gLog, vLog, extLog;
  using TF = typename R::template Tangent<float>;
  using QF = typename R::template Config<float>;
  for(int s = 0; s < kStates; ++s)
  {
    ref.sample(rng);
    const auto q = ref.q();
    const auto a = ref.alpha(), ad = ref.alphaD();
    const QF qf = q.template cast<float>();
    const TF af = a.template cast<float>(), adf = ad.template cast<float>();
    const Eigen::VectorXd tauRef = ref.id(true, true, true);
    idLog.add(err(R::id(q, a, ad), tauRef), err(R::id(qf, af, adf), tauRef));
    const Eigen::VectorXd nleRef = ref.id(true, false, true);
    nleLog.add(err(R::nle(q, a), nleRef), err(R::nle(qf, af), nleRef));
    const Eigen::VectorXd gRef = ref.id(false, false, true);
    gLog.add(err(R::grav(q), gRef), err(R::grav(qf), gRef));
    const Eigen::VectorXd vRef = ref.id(true, false, false);
    vLog.add(err(R::vel(q, a), vRef), err(R::vel(qf, af), vRef));

    // External wrenches on every link (world coordinates at the world origin).
    std::array<typename R::template Wrench<double>, R::nbodies> fext;
    std::array<typename R::template Wrench<float>, R::nbodies> fextF;
    for(int i = 0; i < R::nbodies; ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      for(int c = 0; c < 6; ++c) fext[k](c) = rbdtest::uniform(rng, -5, 5);
      fextF[k] = fext[k].template cast<float>();
      ref.mbc.force[k] = sva::ForceVecd(fext[k]);
    }
    const Eigen::VectorXd extRef = ref.id(true, true, true);
    for(auto & f : ref.mbc.force) f = sva::ForceVecd::Zero();
    extLog.add(err(R::idExt(q, a, ad, fext), extRef), err(R::idExt(qf, af, adf, fextF), extRef));
  }
  idLog.report("inverse_dynamics");
  nleLog.report("nonlinear_effects");
  gLog.report("gravity_torques");
  vLog.report("velocity_torques");
  extLog.report("inverse_dynamics(fext)");
  for(const ErrorLog * l : {&idLog, &nleLog, &gLog, &vLog, &extLog})
  {
    EXPECT_LE(l->worstDouble, kTolDouble);
    EXPECT_LE(l->worstFloat, kTolFloatDynamics);
  }
}

template<class R>
void checkMassMatrixAndForwardDynamics()
{
  Reference<R> ref;
  rbdtest::Rng rng(3);
  rbd::ForwardDynamics fdr(ref.mb());
  ErrorLog hLog, fdLog;
  double worstCond = 0;
  for(int s = 0; s < kStates; ++s)
  {
    ref.sample(rng);
    const auto q = ref.q();
    fdr.computeH(ref.mb(), ref.mbc);
    const Eigen::MatrixXd H = fdr.H();
    hLog.add(err(R::massMatrix(q), H), err(R::massMatrix(typename R::template Config<float>(q.template cast<float>())), H));
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H).eigenvalues();
    const double cond = ev.maxCoeff() / ev.minCoeff();
    if(!(ev.minCoeff() > 0) || cond > 1e12)
    {
      GTEST_SKIP() << "mass matrix singular or cond " << cond << ": forward dynamics undefined (stability issue)";
    }
    worstCond = std::max(worstCond, cond);
    rbd::MultiBodyConfig c = ref.mbc;
    fdr.forwardDynamics(ref.mb(), c);
    const Eigen::VectorXd adRef = rbd::dofToVector(ref.mb(), c.alphaD);
    const auto a = ref.alpha(), tau = ref.torque();
    const double ed = err(R::fd(q, a, tau), adRef);
    const double ef = err(R::fd(typename R::template Config<float>(q.template cast<float>()),
                                typename R::template Tangent<float>(a.template cast<float>()),
                                typename R::template Tangent<float>(tau.template cast<float>())),
                          adRef);
    // Two correct solvers differ by ~cond(H) eps: the bound scales with the conditioning.
    EXPECT_LE(ed, kTolDouble * std::max(1.0, cond * 1e-3)) << "cond(H) = " << cond;
    EXPECT_LE(ef, kTolFloatDynamics * std::max(1.0, cond * 1e-2)) << "cond(H) = " << cond;
    fdLog.add(ed, ef);
  }
  hLog.report("mass_matrix");
  fdLog.report("forward_dynamics");
  std::printf("[ forward_dynamics ] worst cond(H) %.3g\n", worstCond);
  EXPECT_LE(hLog.worstDouble, kTolDouble);
  EXPECT_LE(hLog.worstFloat, kTolFloatDynamics);
}

template<class R>
void checkJacobianAndCoM()
{
  Reference<R> ref;
  rbdtest::Rng rng(4);
  std::vector<rbd::Jacobian> jacs;
  for(int i = 0; i < R::nbodies; ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    // the link origin in its MultiBody body frame
    const Eigen::Vector3d p = ref.X_mb_link[k].inv().translation();
    jacs.emplace_back(ref.mb(), ref.mb().body(i).name(), p);
  }
  ErrorLog jLog, cLog;
  for(int s = 0; s < kStates / 4; ++s)
  {
    ref.sample(rng);
    const auto q = ref.q();
    const auto kin = R::kinematics(q);
    const auto kinF = R::kinematics(typename R::template Config<float>(q.template cast<float>()));
    for(int i = 0; i < R::nbodies; ++i)
    {
      Eigen::MatrixXd full;
      jacs[static_cast<std::size_t>(i)].fullJacobian(ref.mb(), jacs[static_cast<std::size_t>(i)].jacobian(ref.mb(), ref.mbc), full);
      const auto b = static_cast<typename R::Body>(i);
      const auto J = R::template jacobian<double>(b, kin);
      jLog.add(err(J, full), err(R::template jacobian<float>(b, kinF), full));
      ASSERT_EQ(J, R::jacobianQ(b, q));
    }
    const Eigen::Vector3d com = rbd::computeCoM(ref.mb(), ref.mbc);
    cLog.add(err(R::com(q), com), err(R::com(typename R::template Config<float>(q.template cast<float>())), com));
  }
  jLog.report("jacobian");
  cLog.report("center_of_mass");
  EXPECT_LE(jLog.worstDouble, kTolDouble);
  EXPECT_LE(jLog.worstFloat, kTolFloatKinematics);
  EXPECT_LE(cLog.worstDouble, kTolDouble);
  EXPECT_LE(cLog.worstFloat, kTolFloatKinematics);
}

template<class R>
void checkNoAllocation()
{
  Reference<R> ref;
  rbdtest::Rng rng(5);
  ref.sample(rng);
  const auto q = ref.q();
  const auto a = ref.alpha(), ad = ref.alphaD();
  std::array<typename R::template Wrench<double>, R::nbodies> fext;
  for(auto & w : fext) w.setZero();
  double sink = 0;
  long count = 0;
  {
    AllocationScope scope;
    const auto kin = R::kinematics(q);
    sink += R::fk(q)[0].translation.sum() + R::id(q, a, ad).sum() + R::idExt(q, a, ad, fext).sum() + R::nle(q, a).sum() +
            R::grav(q).sum() + R::vel(q, a).sum() + R::massMatrix(q).sum() + R::fd(q, a, ad).sum() +
            R::template jacobian<double>(static_cast<typename R::Body>(R::nbodies - 1), kin).sum() + R::com(q).sum();
    count = scope.count();
  }
  EXPECT_EQ(count, 0) << "heap allocations during generated calls";
  // Sanity of the counter itself: it must see an allocation.
  {
    AllocationScope scope;
    std::vector<double> v(100, sink);
    EXPECT_GT(scope.count(), 0);
  }
}

} // namespace rbdgentest

#define RBDGEN_GENERATED_TESTS(NAME, R)                                                   \
  TEST(Generated_##NAME, ForwardKinematics) { rbdgentest::checkForwardKinematics<R>(); }   \
  TEST(Generated_##NAME, InverseDynamics) { rbdgentest::checkInverseDynamics<R>(); }       \
  TEST(Generated_##NAME, MassMatrixForwardDynamics)                                        \
  {                                                                                        \
    rbdgentest::checkMassMatrixAndForwardDynamics<R>();                                    \
  }                                                                                        \
  TEST(Generated_##NAME, JacobianCoM) { rbdgentest::checkJacobianAndCoM<R>(); }            \
  TEST(Generated_##NAME, NoAllocation) { rbdgentest::checkNoAllocation<R>(); }
