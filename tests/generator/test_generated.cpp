// Every generated function of every robot against the runtime on seeded random states: double
// within 1e-12 (max |generated - runtime| / max(1, max |runtime|)), float within the bounds below;
// no heap allocation during generated calls.
#include <cmath>
#include <limits>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <rbd/CoM.h>
#include <rbd/FA.h>
#include <rbd/Momentum.h>
#include <rbd/FD.h>
#include <rbd/FDDerivatives.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/Jacobian.h>
#include <rbd/parsers/urdf.h>

#include "AllocationCounter.h"
#include "GeneratedReference.h"
#include "GeneratedRobot.h"
#include "ProgrammaticModels.h"
#include "TestModels.h"

namespace rbdgentest
{
/// All robots configured by CMake (robots_list.cpp).
const std::vector<const GeneratedRobot *> & generatedRobots();
} // namespace rbdgentest

namespace
{
using rbdgentest::GeneratedRobot;

constexpr int kStates = 100;
constexpr int kPointStates = 6; ///< states of the point-Jacobian checks (each builds a runtime Jacobian per link)
constexpr double kTolDouble = 1e-12;
// float: unit roundoff 6e-8, grown by the recursion depth and magnitudes (measured worst: ~1e-6).
constexpr double kTolFloatKinematics = 2e-5;
constexpr double kTolFloatDynamics = 2e-4;

using rbdgentest::Reference;

Eigen::VectorXf toFloat(const Eigen::VectorXd & v)
{
  return v.cast<float>();
}

template<class A, class B>
double err(const Eigen::MatrixBase<A> & a, const Eigen::MatrixBase<B> & b)
{
  return rbdtest::relErr(a, b);
}

/// Worst errors of one function over all states, printed at the end of a test.
struct ErrorLog
{
  const char * what;
  double worstDouble = 0, worstFloat = 0;
  void add(double ed, double ef)
  {
    worstDouble = std::max(worstDouble, ed);
    worstFloat = std::max(worstFloat, ef);
  }
  ~ErrorLog() { std::printf("[ %-24s ] worst relative error: double %.3g, float %.3g\n", what, worstDouble, worstFloat); }
};

class Generated : public ::testing::TestWithParam<const GeneratedRobot *>
{
protected:
  const GeneratedRobot & g() const { return *GetParam(); }
};

TEST_P(Generated, ForwardKinematics)
{
  Reference ref(g());
  ASSERT_EQ(ref.mb().nrParams(), g().nq);
  ASSERT_EQ(ref.mb().nrDof(), g().nv);
  ASSERT_EQ(ref.mb().nrBodies(), g().nbodies);
  for(int i = 0; i < g().nbodies; ++i) EXPECT_EQ(ref.mb().body(i).name(), g().bodyNames[i]);
  rbdtest::Rng rng(1);
  ErrorLog log{"forward_kinematics"}, kinLog{"kinematics"};
  Eigen::VectorXd poses(12 * g().nbodies), posesK(12 * g().nbodies);
  Eigen::VectorXf posesF(12 * g().nbodies);
  for(int s = 0; s < kStates; ++s)
  {
    ref.sample(rng);
    const Eigen::VectorXd q = ref.q();
    const Eigen::VectorXf qf = toFloat(q);
    g().d.forwardKinematics(q.data(), poses.data());
    g().d.kinematicsPoses(q.data(), posesK.data());
    g().f.forwardKinematics(qf.data(), posesF.data());
    for(int i = 0; i < g().nbodies; ++i)
    {
      const sva::PTransformd X = ref.X_mb_link[static_cast<std::size_t>(i)] * ref.mbc.bodyPosW[static_cast<std::size_t>(i)];
      Eigen::Matrix<double, 12, 1> expected;
      for(int r = 0; r < 3; ++r)
        for(int c = 0; c < 3; ++c) expected(3 * r + c) = X.rotation()(r, c);
      expected.tail<3>() = X.translation();
      const double ed = err(poses.segment<12>(12 * i), expected);
      const double ef = err(posesF.segment<12>(12 * i), expected);
      ASSERT_LE(ed, kTolDouble) << "link " << g().bodyNames[i];
      ASSERT_LE(ef, kTolFloatKinematics) << "link " << g().bodyNames[i];
      log.add(ed, ef);
      kinLog.add(err(posesK.segment<12>(12 * i), expected), 0);
    }
  }
  EXPECT_LE(kinLog.worstDouble, kTolDouble);
}

TEST_P(Generated, InverseDynamics)
{
  Reference ref(g());
  rbdtest::Rng rng(2);
  ErrorLog idLog{"inverse_dynamics"}, nleLog{"nonlinear_effects"}, gLog{"gravity_torques"}, vLog{"velocity_torques"},
      extLog{"inverse_dynamics(fext)"};
  const int nv = g().nv;
  Eigen::VectorXd tau(nv);
  Eigen::VectorXf tauF(nv);
  for(int s = 0; s < kStates; ++s)
  {
    ref.sample(rng);
    const Eigen::VectorXd q = ref.q(), a = ref.alpha(), ad = ref.alphaD();
    const Eigen::VectorXf qf = toFloat(q), af = toFloat(a), adf = toFloat(ad);
    auto check = [&](ErrorLog & log, const Eigen::VectorXd & expected) {
      log.add(err(tau, expected), err(tauF, expected));
    };
    g().d.inverseDynamics(q.data(), a.data(), ad.data(), tau.data());
    g().f.inverseDynamics(qf.data(), af.data(), adf.data(), tauF.data());
    check(idLog, ref.id(true, true, true));
    g().d.nonlinearEffects(q.data(), a.data(), tau.data());
    g().f.nonlinearEffects(qf.data(), af.data(), tauF.data());
    check(nleLog, ref.id(true, false, true));
    g().d.gravityTorques(q.data(), tau.data());
    g().f.gravityTorques(qf.data(), tauF.data());
    check(gLog, ref.id(false, false, true));
    g().d.velocityTorques(q.data(), a.data(), tau.data());
    g().f.velocityTorques(qf.data(), af.data(), tauF.data());
    check(vLog, ref.id(true, false, false));

    // An external wrench on every link (world coordinates at the world origin).
    Eigen::VectorXd fext(6 * g().nbodies);
    for(int i = 0; i < fext.size(); ++i) fext(i) = rbdtest::uniform(rng, -5, 5);
    const Eigen::VectorXf fextF = toFloat(fext);
    Reference & r = ref;
    for(int i = 0; i < g().nbodies; ++i)
      r.mbc.force[static_cast<std::size_t>(i)] = sva::ForceVecd(Eigen::Matrix<double, 6, 1>(fext.segment<6>(6 * i)));
    const Eigen::VectorXd extExpected = ref.id(true, true, true);
    for(auto & f : r.mbc.force) f = sva::ForceVecd::Zero();
    g().d.inverseDynamicsExt(q.data(), a.data(), ad.data(), fext.data(), tau.data());
    g().f.inverseDynamicsExt(qf.data(), af.data(), adf.data(), fextF.data(), tauF.data());
    check(extLog, extExpected);
  }
  for(const ErrorLog * l : {&idLog, &nleLog, &gLog, &vLog, &extLog})
  {
    EXPECT_LE(l->worstDouble, kTolDouble) << l->what;
    EXPECT_LE(l->worstFloat, kTolFloatDynamics) << l->what;
  }
}

TEST_P(Generated, MassMatrixAndForwardDynamics)
{
  Reference ref(g());
  rbdtest::Rng rng(3);
  rbd::ForwardDynamics fdr(ref.mb());
  ErrorLog hLog{"mass_matrix"}, hpLog{"mass_matrix_packed"}, fdLog{"forward_dynamics"}, abaLog{"forward_dynamics_aba"}, crbaLog{"forward_dynamics_crba"};
  std::printf("[ %-24s ] %s\n", "forward_dynamics", g().forwardDynamicsAlgorithm);
  const int nv = g().nv;
  Eigen::MatrixXd H(nv, nv);
  Eigen::MatrixXf HF(nv, nv);
  Eigen::VectorXd ad(nv);
  Eigen::VectorXf adF(nv);
  double worstCond = 0;
  bool singular = false;
  for(int s = 0; s < kStates; ++s)
  {
    ref.sample(rng);
    const Eigen::VectorXd q = ref.q(), a = ref.alpha(), tau = ref.torque();
    const Eigen::VectorXf qf = toFloat(q), af = toFloat(a), tauf = toFloat(tau);
    fdr.computeH(ref.mb(), ref.mbc);
    const Eigen::MatrixXd Href = fdr.H();
    g().d.massMatrix(q.data(), H.data());
    g().f.massMatrix(qf.data(), HF.data());
    hLog.add(err(H, Href), err(HF, Href));
    // the packed entries (and 0 for those it leaves out) against the runtime's H
    g().d.massMatrixPacked(q.data(), H.data());
    g().f.massMatrixPacked(qf.data(), HF.data());
    hpLog.add(err(H, Href), err(HF, Href));
    // Massless-subtree policy: no forward dynamics exactly where the mass matrix is singular
    // (rank-revealing LU of the runtime's H).
    const bool rankDeficient = Eigen::FullPivLU<Eigen::MatrixXd>(Href).rank() < nv;
    ASSERT_EQ(rankDeficient, !g().hasForwardDynamics) << "state " << s << ": has_forward_dynamics = " << g().hasForwardDynamics;
    if(rankDeficient)
    {
      ASSERT_EQ(g().d.forwardDynamics, nullptr);
      singular = true;
      continue;
    }
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Href).eigenvalues();
    const double cond = ev.maxCoeff() / ev.minCoeff();
    worstCond = std::max(worstCond, cond);
    rbd::MultiBodyConfig c = ref.mbc;
    fdr.forwardDynamics(ref.mb(), c);
    const Eigen::VectorXd adRef = rbd::dofToVector(ref.mb(), c.alphaD);
    // forward_dynamics (the chosen algorithm), then each algorithm on its own.
    using Fd = void (*)(const double *, const double *, const double *, double *);
    using FdF = void (*)(const float *, const float *, const float *, float *);
    const std::pair<Fd, FdF> variants[] = {{g().d.forwardDynamics, g().f.forwardDynamics},
                                           {g().d.forwardDynamicsAba, g().f.forwardDynamicsAba},
                                           {g().d.forwardDynamicsCrba, g().f.forwardDynamicsCrba}};
    ErrorLog * logs[] = {&fdLog, &abaLog, &crbaLog};
    for(int vi = 0; vi < 3; ++vi)
    {
      variants[vi].first(q.data(), a.data(), tau.data(), ad.data());
      variants[vi].second(qf.data(), af.data(), tauf.data(), adF.data());
      const double ed = err(ad, adRef), ef = err(adF, adRef);
      // Two backward-stable solvers differ by ~cond(H) eps: the bound grows with the conditioning.
      EXPECT_LE(ed, kTolDouble * std::max(1.0, cond * 1e-3)) << logs[vi]->what << ", cond(H) = " << cond;
      EXPECT_LE(ef, kTolFloatDynamics * std::max(1.0, cond * 1e-3)) << logs[vi]->what << ", cond(H) = " << cond;
      logs[vi]->add(ed, ef);
    }
  }
  std::printf("[ %-24s ] worst cond(H) %.3g%s\n", "forward_dynamics", worstCond,
              singular ? " (singular mass matrix at every state: has_forward_dynamics = false)" : "");
  for(const ErrorLog * l : {&hLog, &hpLog})
  {
    EXPECT_LE(l->worstDouble, kTolDouble) << l->what;
    EXPECT_LE(l->worstFloat, kTolFloatDynamics) << l->what;
  }
}

TEST_P(Generated, JacobianAndCenterOfMass)
{
  Reference ref(g());
  rbdtest::Rng rng(4);
  std::vector<rbd::Jacobian> jacs;
  for(int i = 0; i < g().nbodies; ++i)
  {
    // the link origin, in its MultiBody body frame
    const Eigen::Vector3d p = ref.X_mb_link[static_cast<std::size_t>(i)].translation();
    jacs.emplace_back(ref.mb(), ref.mb().body(i).name(), p);
  }
  ErrorLog jLog{"jacobian"}, jqLog{"jacobian(body, q)"}, jpLog{"jacobian(body, q, point)"},
      jkpLog{"jacobian(body, kin, point)"}, cLog{"center_of_mass"}, ckLog{"center_of_mass(kin)"};
  const int nv = g().nv;
  Eigen::MatrixXd J(6, nv), JQ(6, nv), JP(6, nv), JKP(6, nv), full, fullP;
  Eigen::MatrixXf JF(6, nv), JQF(6, nv), JPF(6, nv), JKPF(6, nv);
  Eigen::Vector3d com, comK;
  Eigen::Vector3f comF, comKF;
  for(int s = 0; s < kStates / 4; ++s)
  {
    ref.sample(rng);
    const Eigen::VectorXd q = ref.q();
    const Eigen::VectorXf qf = toFloat(q);
    // a point of each link (link coordinates), new for every state: a tool tip, a foot sole...
    const Eigen::Vector3d point = rbdtest::uniformVec<3>(rng, -0.5, 0.5);
    const Eigen::Vector3f pointF = point.cast<float>();
    for(int i = 0; i < g().nbodies; ++i)
    {
      auto & jac = jacs[static_cast<std::size_t>(i)];
      jac.fullJacobian(ref.mb(), jac.jacobian(ref.mb(), ref.mbc), full);
      g().d.jacobian(i, q.data(), J.data());
      g().d.jacobianQ(i, q.data(), JQ.data());
      g().f.jacobian(i, qf.data(), JF.data());
      g().f.jacobianQ(i, qf.data(), JQF.data());
      jLog.add(err(J, full), err(JF, full));
      jqLog.add(err(JQ, full), err(JQF, full));
      if(s >= kPointStates) continue; // the point variants (a runtime Jacobian per link) on fewer states
      // the runtime's Jacobian at the same point, given in the MultiBody body frame
      const sva::PTransformd & X = ref.X_mb_link[static_cast<std::size_t>(i)];
      rbd::Jacobian jacP(ref.mb(), ref.mb().body(i).name(), X.translation() + X.rotation().transpose() * point);
      jacP.fullJacobian(ref.mb(), jacP.jacobian(ref.mb(), ref.mbc), fullP);
      g().d.jacobianPoint(i, q.data(), point.data(), JP.data());
      g().d.jacobianKinPoint(i, q.data(), point.data(), JKP.data());
      g().f.jacobianPoint(i, qf.data(), pointF.data(), JPF.data());
      g().f.jacobianKinPoint(i, qf.data(), pointF.data(), JKPF.data());
      jpLog.add(err(JP, fullP), err(JPF, fullP));
      jkpLog.add(err(JKP, fullP), err(JKPF, fullP));
    }
    g().d.centerOfMass(q.data(), com.data());
    g().f.centerOfMass(qf.data(), comF.data());
    const Eigen::Vector3d comRef = rbd::computeCoM(ref.mb(), ref.mbc);
    cLog.add(err(com, comRef), err(comF, comRef));
    g().d.centerOfMassKin(q.data(), comK.data());
    g().f.centerOfMassKin(qf.data(), comKF.data());
    ckLog.add(err(comK, comRef), err(comKF, comRef));
  }
  for(const ErrorLog * l : {&jLog, &jqLog, &jpLog, &jkpLog})
  {
    EXPECT_LE(l->worstDouble, kTolDouble) << l->what;
    EXPECT_LE(l->worstFloat, kTolFloatKinematics) << l->what;
  }
  EXPECT_LE(cLog.worstDouble, kTolDouble);
  EXPECT_LE(cLog.worstFloat, kTolFloatKinematics);
  EXPECT_LE(ckLog.worstDouble, kTolDouble);
  EXPECT_LE(ckLog.worstFloat, kTolFloatKinematics);
}

TEST_P(Generated, VelocitiesAccelerationsMomentum)
{
  Reference ref(g());
  rbdtest::Rng rng(6);
  std::vector<rbd::Jacobian> jacs;
  for(int i = 0; i < g().nbodies; ++i)
    jacs.emplace_back(ref.mb(), ref.mb().body(i).name(), ref.X_mb_link[static_cast<std::size_t>(i)].translation());
  rbd::CoMJacobian comJac(ref.mb());
  rbd::CentroidalMomentumMatrix cmm(ref.mb());
  ErrorLog vLog{"body_velocities"}, aLog{"body_accelerations"}, jdLog{"jacobian_dot_times_alpha"},
      jdkLog{"jacobian_dot_times_alpha(body, kin, alpha)"},
      cjLog{"com_jacobian"}, cmmLog{"centroidal_momentum_matrix"};
  const int nv = g().nv, nb = g().nbodies;
  Eigen::VectorXd v(6 * nb), a(6 * nb);
  Eigen::VectorXf vF(6 * nb), aF(6 * nb);
  Eigen::Matrix<double, 6, 1> jd, jdk;
  Eigen::Matrix<float, 6, 1> jdF, jdkF;
  Eigen::MatrixXd CJ(3, nv), A(6, nv);
  Eigen::MatrixXf CJF(3, nv), AF(6, nv);
  for(int s = 0; s < kStates / 4; ++s)
  {
    ref.sample(rng);
    rbd::forwardAcceleration(ref.mb(), ref.mbc);
    const Eigen::VectorXd q = ref.q(), al = ref.alpha(), ad = ref.alphaD();
    const Eigen::VectorXf qf = toFloat(q), alf = toFloat(al), adf = toFloat(ad);
    g().d.bodyVelocities(q.data(), al.data(), v.data());
    g().f.bodyVelocities(qf.data(), alf.data(), vF.data());
    g().d.bodyAccelerations(q.data(), al.data(), ad.data(), a.data());
    g().f.bodyAccelerations(qf.data(), alf.data(), adf.data(), aF.data());
    Eigen::VectorXd vRef(6 * nb), aRef(6 * nb);
    for(int i = 0; i < nb; ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      vRef.segment<6>(6 * i) = (ref.X_mb_link[k] * ref.mbc.bodyVelB[k]).vector();
      aRef.segment<6>(6 * i) = (ref.X_mb_link[k] * ref.mbc.bodyAccB[k]).vector();
      g().d.jacobianDotTimesAlpha(i, q.data(), al.data(), jd.data());
      g().f.jacobianDotTimesAlpha(i, qf.data(), alf.data(), jdF.data());
      const Eigen::Matrix<double, 6, 1> jdRef = jacs[k].normalAcceleration(ref.mb(), ref.mbc).vector();
      jdLog.add(err(jd, jdRef), err(jdF, jdRef));
      g().d.jacobianDotTimesAlphaKin(i, q.data(), al.data(), jdk.data());
      g().f.jacobianDotTimesAlphaKin(i, qf.data(), alf.data(), jdkF.data());
      jdkLog.add(err(jdk, jdRef), err(jdkF, jdRef));
    }
    vLog.add(err(v, vRef), err(vF, vRef));
    aLog.add(err(a, aRef), err(aF, aRef));
    g().d.comJacobian(q.data(), CJ.data());
    g().f.comJacobian(qf.data(), CJF.data());
    const Eigen::MatrixXd CJRef = comJac.jacobian(ref.mb(), ref.mbc);
    cjLog.add(err(CJ, CJRef), err(CJF, CJRef));
    g().d.centroidalMomentumMatrix(q.data(), A.data());
    g().f.centroidalMomentumMatrix(qf.data(), AF.data());
    cmm.computeMatrix(ref.mb(), ref.mbc, rbd::computeCoM(ref.mb(), ref.mbc));
    cmmLog.add(err(A, cmm.matrix()), err(AF, cmm.matrix()));
  }
  for(const ErrorLog * l : {&vLog, &aLog, &jdLog, &jdkLog, &cjLog, &cmmLog})
  {
    EXPECT_LE(l->worstDouble, kTolDouble) << l->what;
    EXPECT_LE(l->worstFloat, kTolFloatDynamics) << l->what;
  }
}

// Derivatives (robots generated with derivatives): against the runtime's analytic derivatives
// (rbd/IDDerivatives.h, FDDerivatives.h), themselves tested against long double differences and
// AutoDiff (tests/dynamics/test_derivatives.cpp). d alphaD carries H^-1: bounds grow with cond(H).
class GeneratedDerivatives : public Generated
{
};

TEST_P(GeneratedDerivatives, MatchRuntime)
{
  ASSERT_NE(g().d.inverseDynamicsDerivatives, nullptr);
  Reference ref(g());
  rbdtest::Rng rng(6);
  const int nv = g().nv;
  ErrorLog dqLog{"dtau_dq"}, daLog{"dtau_dalpha"}, fqLog{"dalphaD_dq"}, faLog{"dalphaD_dalpha"}, miLog{"Minv"},
      adLog{"fd_derivatives alphaD"};
  Eigen::MatrixXd dq(nv, nv), da(nv, nv), fq(nv, nv), fa(nv, nv), mi(nv, nv);
  Eigen::MatrixXf dqF(nv, nv), daF(nv, nv), fqF(nv, nv), faF(nv, nv), miF(nv, nv);
  Eigen::VectorXd ad(nv);
  Eigen::VectorXf adF(nv);
  rbd::InverseDynamicsDerivatives idr(ref.mb());
  rbd::ForwardDynamicsDerivatives fdr(ref.mb());
  for(int s = 0; s < kStates / 4; ++s)
  {
    ref.sample(rng);
    const Eigen::VectorXd q = ref.q(), a = ref.alpha(), acc = ref.alphaD(), tau = ref.torque();
    const Eigen::VectorXf qf = toFloat(q), af = toFloat(a), accf = toFloat(acc), tauf = toFloat(tau);
    idr.inverseDynamicsDerivatives(ref.mb(), ref.mbc);
    g().d.inverseDynamicsDerivatives(q.data(), a.data(), acc.data(), dq.data(), da.data());
    g().f.inverseDynamicsDerivatives(qf.data(), af.data(), accf.data(), dqF.data(), daF.data());
    dqLog.add(err(dq, idr.dtauDq()), err(dqF, idr.dtauDq()));
    daLog.add(err(da, idr.dtauDalpha()), err(daF, idr.dtauDalpha()));
    if(!g().d.forwardDynamicsDerivatives) continue;
    fdr.forwardDynamicsDerivatives(ref.mb(), ref.mbc);
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(fdr.Minv())).eigenvalues();
    const double grow = std::max(1.0, ev.maxCoeff() / ev.minCoeff() * 1e-3);
    g().d.forwardDynamicsDerivatives(q.data(), a.data(), tau.data(), ad.data(), fq.data(), fa.data(), mi.data());
    g().f.forwardDynamicsDerivatives(qf.data(), af.data(), tauf.data(), adF.data(), fqF.data(), faF.data(), miF.data());
    const std::pair<ErrorLog *, std::pair<double, double>> checks[] = {
        {&adLog, {err(ad, fdr.alphaD()), err(adF, fdr.alphaD())}},
        {&fqLog, {err(fq, fdr.dalphaDDq()), err(fqF, fdr.dalphaDDq())}},
        {&faLog, {err(fa, fdr.dalphaDDalpha()), err(faF, fdr.dalphaDDalpha())}},
        {&miLog, {err(mi, fdr.Minv()), err(miF, fdr.Minv())}}};
    for(const auto & [log, e] : checks)
    {
      // alphaD = H^-1 (tau - C) and Minv differ between two solvers by ~cond(H) eps; d alphaD/dq =
      // -H^-1 dID/dq (q, alpha, alphaD) applies H^-1 to a quantity that already carries that error: cond^2
      const double g = log == &fqLog ? grow * grow : grow;
      EXPECT_LE(e.first, 10 * kTolDouble * g) << log->what << ", state " << s;
      EXPECT_LE(e.second, 10 * kTolFloatDynamics * g) << log->what << ", state " << s;
      log->add(e.first, e.second);
    }
  }
  for(const ErrorLog * l : {&dqLog, &daLog})
  {
    EXPECT_LE(l->worstDouble, kTolDouble) << l->what;
    EXPECT_LE(l->worstFloat, kTolFloatDynamics) << l->what;
  }
}

/// The free joints whose ancestors are all fixed (a floating base): (dof offset, body index).
std::vector<std::pair<int, int>> freeRoots(const rbd::MultiBody & mb)
{
  std::vector<std::pair<int, int>> roots;
  for(int j = 0; j < mb.nrJoints(); ++j)
  {
    if(mb.joint(j).type() != rbd::Joint::Free || !mb.joint(j).forward()) continue;
    bool fixedAbove = true;
    for(int b = mb.predecessor(j); b >= 0; b = mb.parent(b))
      fixedAbove = fixedAbove && mb.joint(b).type() == rbd::Joint::Fixed;
    if(fixedAbove) roots.emplace_back(mb.jointPosInDof(j), mb.successor(j));
  }
  return roots;
}

/// Fills 256 KB of the stack below the caller's frame with `value`: the frames of the calls the
/// caller makes next start from that content (their locals before they write them).
[[gnu::noinline]] void fillStack(double value)
{
  constexpr std::size_t n = (256u << 10) / sizeof(double);
  volatile double junk[n];
  for(std::size_t i = 0; i < n; ++i) junk[i] = value;
}

// The derivatives read no value they did not write: the same call after the stack (the functions'
// locals, e.g. forward_dynamics_derivatives' IdDerivatives) and the output matrices were filled
// with NaN, then with zeros, gives finite and bitwise equal outputs. (Up to 8 dofs the products
// -M^-1 dID are dense and read dID's entries off the dof tree's paths: two_fingers, a branching
// tree of 5 dofs, left NaN there when only the paths were written.)
TEST_P(GeneratedDerivatives, IgnoreWhatTheStackHeld)
{
  Reference ref(g());
  rbdtest::Rng rng(13);
  const int nv = g().nv;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(int s = 0; s < 4; ++s)
  {
    ref.sample(rng);
    const Eigen::VectorXd q = ref.q(), a = ref.alpha(), acc = ref.alphaD(), tau = ref.torque();
    std::vector<Eigen::MatrixXd> out[2];
    for(int k = 0; k < 2; ++k)
    {
      const double fill = k == 0 ? nan : 0.0;
      std::vector<Eigen::MatrixXd> & o = out[k];
      o.assign(5, Eigen::MatrixXd::Constant(nv, nv, fill));
      o.push_back(Eigen::MatrixXd::Constant(nv, 1, fill));
      fillStack(fill);
      g().d.inverseDynamicsDerivatives(q.data(), a.data(), acc.data(), o[0].data(), o[1].data());
      if(!g().d.forwardDynamicsDerivatives) continue;
      fillStack(fill);
      g().d.forwardDynamicsDerivatives(q.data(), a.data(), tau.data(), o[5].data(), o[2].data(), o[3].data(), o[4].data());
    }
    const char * names[] = {"dtau_dq", "dtau_dalpha", "dalphaD_dq", "dalphaD_dalpha", "Minv", "alphaD"};
    for(std::size_t m = 0; m < out[0].size(); ++m)
    {
      if(m >= 2 && !g().d.forwardDynamicsDerivatives) break;
      EXPECT_TRUE(out[0][m].allFinite()) << names[m] << ", state " << s;
      EXPECT_TRUE(out[0][m].cwiseEqual(out[1][m]).all()) << names[m] << ", state " << s;
    }
  }
}

// A floating base's pose moves the forward dynamics through gravity alone (no contacts, no world
// wrenches): the same motion in a frame that translates, gravity turned by a rotation. Over its six
// dofs d alphaD/dq is therefore zero but in the base's linear acceleration, which turns with gravity:
// d alphaD_lin / d w = -[gamma]x, gamma = E g_up (E: world to base). Its linear velocity adds a
// uniform velocity (Galilean: no force) and, alphaD being the derivative of the base-frame velocity,
// d alphaD / d alpha_lin = -[w]x in the linear rows (a single body's v' = f/m - w x v), zero
// elsewhere. Laws, not either code: the runtime's -H^-1 dID sums to them within rounding x
// cond(H)^2, the generated header writes them.
class GeneratedFloatingBaseDerivatives : public Generated
{
};

TEST_P(GeneratedFloatingBaseDerivatives, BaseColumnsTurnWithGravity)
{
  Reference ref(g());
  const auto roots = freeRoots(ref.mb());
  ASSERT_FALSE(roots.empty());
  ASSERT_NE(g().d.forwardDynamicsDerivatives, nullptr);
  rbdtest::Rng rng(9);
  const int nv = g().nv;
  Eigen::MatrixXd fq(nv, nv), fa(nv, nv), mi(nv, nv);
  Eigen::VectorXd ad(nv);
  rbd::ForwardDynamicsDerivatives fdr(ref.mb());
  for(int s = 0; s < kStates / 4; ++s)
  {
    ref.sample(rng);
    const Eigen::VectorXd q = ref.q(), a = ref.alpha(), tau = ref.torque();
    fdr.forwardDynamicsDerivatives(ref.mb(), ref.mbc);
    g().d.forwardDynamicsDerivatives(q.data(), a.data(), tau.data(), ad.data(), fq.data(), fa.data(), mi.data());
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(fdr.Minv())).eigenvalues();
    const double grow = std::max(1.0, ev.maxCoeff() / ev.minCoeff() * 1e-3);
    for(const auto & [o, body] : roots)
    {
      const Eigen::Vector3d gamma = ref.mbc.bodyPosW[static_cast<std::size_t>(body)].rotation() * ref.mbc.gravity;
      Eigen::MatrixXd law = Eigen::MatrixXd::Zero(nv, 6), lawV = Eigen::MatrixXd::Zero(nv, 3);
      law.block<3, 3>(o + 3, 0) = -sva::vector3ToCrossMatrix(gamma);
      lawV.block<3, 3>(o + 3, 0) = -sva::vector3ToCrossMatrix(Eigen::Vector3d(a.segment<3>(o)));
      EXPECT_LE(err(fq.middleCols(o, 6), law), 1e-14) << "generated (the rotation's rounding), state " << s;
      EXPECT_LE(err(fdr.dalphaDDq().middleCols(o, 6), law), 10 * kTolDouble * grow * grow) << "runtime, state " << s;
      EXPECT_EQ(err(fa.middleCols(o + 3, 3), lawV), 0.0) << "generated, state " << s;
      EXPECT_LE(err(fdr.dalphaDDalpha().middleCols(o + 3, 3), lawV), 10 * kTolDouble * grow * grow) << "runtime, state " << s;
    }
  }
}

TEST_P(Generated, NoHeapAllocation)
{
  Reference ref(g());
  rbdtest::Rng rng(5);
  ref.sample(rng);
  const Eigen::VectorXd q = ref.q(), a = ref.alpha(), ad = ref.alphaD();
  const Eigen::Vector3d point(0.1, -0.2, 0.3);
  const int nv = g().nv, nb = g().nbodies;
  Eigen::VectorXd out(std::max(12 * nb, 6 * nv) + nv * nv), fext = Eigen::VectorXd::Zero(6 * nb);
  Eigen::MatrixXd dA(nv, nv), dB(nv, nv), dC(nv, nv);
  long count = 0;
  {
    rbdgentest::AllocationScope scope;
    g().d.forwardKinematics(q.data(), out.data());
    g().d.kinematicsPoses(q.data(), out.data());
    g().d.inverseDynamics(q.data(), a.data(), ad.data(), out.data());
    g().d.inverseDynamicsExt(q.data(), a.data(), ad.data(), fext.data(), out.data());
    g().d.nonlinearEffects(q.data(), a.data(), out.data());
    g().d.velocityTorques(q.data(), a.data(), out.data());
    g().d.gravityTorques(q.data(), out.data());
    g().d.massMatrix(q.data(), out.data());
    if(g().d.forwardDynamics) g().d.forwardDynamics(q.data(), a.data(), ad.data(), out.data());
    g().d.jacobian(nb - 1, q.data(), out.data());
    g().d.jacobianQ(nb - 1, q.data(), out.data());
    g().d.jacobianPoint(nb - 1, q.data(), point.data(), out.data());
    g().d.jacobianKinPoint(nb - 1, q.data(), point.data(), out.data());
    g().d.jacobianDotTimesAlphaKin(nb - 1, q.data(), a.data(), out.data());
    g().d.centerOfMass(q.data(), out.data());
    g().d.centerOfMassKin(q.data(), out.data());
    g().d.bodyVelocities(q.data(), a.data(), out.data());
    g().d.bodyAccelerations(q.data(), a.data(), ad.data(), out.data());
    g().d.jacobianDotTimesAlpha(nb - 1, q.data(), a.data(), out.data());
    g().d.comJacobian(q.data(), out.data());
    g().d.centroidalMomentumMatrix(q.data(), out.data());
    if(g().d.inverseDynamicsDerivatives)
      g().d.inverseDynamicsDerivatives(q.data(), a.data(), ad.data(), dA.data(), dB.data());
    if(g().d.forwardDynamicsDerivatives)
      g().d.forwardDynamicsDerivatives(q.data(), a.data(), ad.data(), out.data(), dA.data(), dB.data(), dC.data());
    count = scope.count();
  }
  EXPECT_EQ(count, 0) << "heap allocations during generated calls";
  {
    // the counter itself must see an allocation
    rbdgentest::AllocationScope scope;
    std::vector<double> v(100, out(0));
    EXPECT_GT(scope.count(), 0);
  }
}

std::string robotName(const ::testing::TestParamInfo<const GeneratedRobot *> & info)
{
  return info.param->name;
}

INSTANTIATE_TEST_SUITE_P(Robots, Generated, ::testing::ValuesIn(rbdgentest::generatedRobots()), robotName);

/// The robots generated with DERIVATIVES (all but the largest real ones: tests/generator/CMakeLists.txt).
std::vector<const GeneratedRobot *> robotsWithDerivatives()
{
  std::vector<const GeneratedRobot *> out;
  for(const GeneratedRobot * r : rbdgentest::generatedRobots())
    if(r->d.inverseDynamicsDerivatives) out.push_back(r);
  return out;
}
INSTANTIATE_TEST_SUITE_P(Robots, GeneratedDerivatives, ::testing::ValuesIn(robotsWithDerivatives()), robotName);

/// Those with a floating base (--floating-base) and forward dynamics.
std::vector<const GeneratedRobot *> floatingBaseRobotsWithDerivatives()
{
  std::vector<const GeneratedRobot *> out;
  for(const GeneratedRobot * r : robotsWithDerivatives())
    if(r->floatingBase && r->d.forwardDynamicsDerivatives) out.push_back(r);
  return out;
}
INSTANTIATE_TEST_SUITE_P(Robots, GeneratedFloatingBaseDerivatives, ::testing::ValuesIn(floatingBaseRobotsWithDerivatives()),
                         robotName);

} // namespace
