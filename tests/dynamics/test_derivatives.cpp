// Analytic derivatives of inverse and forward dynamics (rbd::InverseDynamicsDerivatives,
// rbd::ForwardDynamicsDerivatives) against two independent witnesses:
//  - central differences with one Richardson step of the runtime's ID and FD in long double,
//    along q ⊕ ε e_m (rbd::integrateConfiguration: the exponential of each joint) and alpha + ε e_m;
//  - the runtime's ID evaluated with Eigen's forward-mode AutoDiffScalar, in double, with
//    q(δ) = q0 + (dq/dt)(q0, δ) (rbd::configurationDerivative: the same tangent to first order).
// On random trees with every joint type in both directions, free and planar roots, external forces.

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <rbd/FDDerivatives.h>
#include <rbd/IDDerivatives.h>

#include "DynTestUtils.h"

namespace
{

using dyntest::MatX;
using dyntest::VecX;
using LD = long double;

/// Models: allJointsModels (roots Fixed, Free with backward chain, Planar) and random trees.
std::vector<rbd::MultiBody> models(rbdtest::Rng & rng)
{
  std::vector<rbd::MultiBody> out;
  for(auto & r : dyntest::allJointsModels(rng)) out.push_back(r.mb);
  for(int n : {1, 3, 7, 12}) out.push_back(dyntest::randomModel(rng, n, 0.4));
  out.push_back(dyntest::randomModel(rng, 9, 0.3, true));
  return out;
}

template<typename T>
rbd::MultiBodyConfigTpl<T> state(rbdtest::Rng & rng, const rbd::MultiBodyTpl<T> & mb)
{
  rbd::MultiBodyConfigTpl<T> mbc(mb);
  rbdtest::randomState<T>(rng, mb, mbc);
  dyntest::randomForces(rng, mbc);
  mbc.gravity = sva::Vector3<T>(T(0.3), T(-0.7), T(9.81));
  return mbc;
}

/// tau = ID(q, alpha, alphaD) with flat vectors (and the config's forces and gravity).
template<typename T>
VecX<T> idFlat(const rbd::MultiBodyTpl<T> & mb, rbd::MultiBodyConfigTpl<T> mbc, const VecX<T> & q, const VecX<T> & alpha,
               const VecX<T> & alphaD)
{
  rbd::vectorToParam<T>(q, mbc.q);
  rbd::vectorToDof<T>(alpha, mbc.alpha);
  rbd::vectorToDof<T>(alphaD, mbc.alphaD);
  dyntest::kinematics(mb, mbc);
  rbd::InverseDynamicsTpl<T> id(mb);
  id.inverseDynamics(mb, mbc);
  return dyntest::dofOf(mb, mbc.jointTorque);
}

/// alphaD = FD(q, alpha, tau).
template<typename T>
VecX<T> fdFlat(const rbd::MultiBodyTpl<T> & mb, rbd::MultiBodyConfigTpl<T> mbc, const VecX<T> & q, const VecX<T> & alpha,
               const VecX<T> & tau)
{
  rbd::vectorToParam<T>(q, mbc.q);
  rbd::vectorToDof<T>(alpha, mbc.alpha);
  rbd::vectorToDof<T>(tau, mbc.jointTorque);
  dyntest::kinematics(mb, mbc);
  rbd::ForwardDynamicsTpl<T> fd(mb);
  fd.forwardDynamics(mb, mbc);
  return dyntest::dofOf(mb, mbc.alphaD);
}

/// Columns d f / d q_m (tangent) and d f / d alpha_m of f(q, alpha) by Richardson central differences.
template<typename F>
std::pair<MatX<LD>, MatX<LD>> numericJacobians(const rbd::MultiBodyTpl<LD> & mb, const VecX<LD> & q,
                                               const VecX<LD> & alpha, F f)
{
  const LD h = 1e-3L;
  MatX<LD> dq(mb.nrDof(), mb.nrDof()), da(mb.nrDof(), mb.nrDof());
  for(int m = 0; m < mb.nrDof(); ++m)
  {
    dq.col(m) = dyntest::derivative<LD>(
        [&](LD e) {
          const VecX<LD> dqm = VecX<LD>::Unit(mb.nrDof(), m) * e;
          return VecX<LD>(f(rbd::integrateConfiguration(mb, q, dqm), alpha));
        },
        h);
    da.col(m) = dyntest::derivative<LD>(
        [&](LD e) { return VecX<LD>(f(q, VecX<LD>(alpha + VecX<LD>::Unit(mb.nrDof(), m) * e))); }, h);
  }
  return {dq, da};
}

// Richardson central differences in long double with h = 1e-3: truncation O(h^4) ~ 1e-12 times the
// fifth derivatives (O(1..100) on these models), round-off ~ 1e-19 / 1e-3; the analytic result in
// long double is exact to ~1e-17. Measured 4e-14; bound 1e-11 relative to max(1, max |d|) (FD: 1e-8, H^-1 amplifies).
TEST(Derivatives, InverseDynamicsMatchesLongDoubleDifferences)
{
  rbdtest::Rng rng(1501);
  double worstQ = 0, worstA = 0;
  for(const auto & mbD : models(rng))
  {
    const rbd::MultiBodyTpl<LD> mb = dyntest::castModel<LD>(mbD);
    for(int trial = 0; trial < 3; ++trial)
    {
      rbd::MultiBodyConfigTpl<LD> mbc = state<LD>(rng, mb);
      dyntest::kinematics(mb, mbc);
      rbd::InverseDynamicsDerivativesTpl<LD> d(mb);
      d.sInverseDynamicsDerivatives(mb, mbc);
      const VecX<LD> q = dyntest::qOf(mb, mbc), alpha = dyntest::dofOf(mb, mbc.alpha),
                     alphaD = dyntest::dofOf(mb, mbc.alphaD);
      const auto [dq, da] = numericJacobians(
          mb, q, alpha, [&](const VecX<LD> & qq, const VecX<LD> & aa) { return idFlat(mb, mbc, qq, aa, alphaD); });
      EXPECT_MAT_NEAR(d.tau(), idFlat(mb, mbc, q, alpha, alphaD), 1e-15);
      EXPECT_MAT_NEAR(d.dtauDq(), dq, 1e-11);
      EXPECT_MAT_NEAR(d.dtauDalpha(), da, 1e-11);
      worstQ = std::max(worstQ, rbdtest::relErr(d.dtauDq(), dq));
      worstA = std::max(worstA, rbdtest::relErr(d.dtauDalpha(), da));
    }
  }
  std::printf("dtau/dq vs long double differences: %.2e, dtau/dalpha: %.2e\n", worstQ, worstA);
}

TEST(Derivatives, ForwardDynamicsMatchesLongDoubleDifferences)
{
  rbdtest::Rng rng(1502);
  double worstQ = 0, worstA = 0, worstMinv = 0;
  for(const auto & mbD : models(rng))
  {
    const rbd::MultiBodyTpl<LD> mb = dyntest::castModel<LD>(mbD);
    for(int trial = 0; trial < 3; ++trial)
    {
      rbd::MultiBodyConfigTpl<LD> mbc = state<LD>(rng, mb);
      dyntest::kinematics(mb, mbc);
      rbd::ForwardDynamicsDerivativesTpl<LD> d(mb);
      d.sForwardDynamicsDerivatives(mb, mbc);
      const VecX<LD> q = dyntest::qOf(mb, mbc), alpha = dyntest::dofOf(mb, mbc.alpha),
                     tau = dyntest::dofOf(mb, mbc.jointTorque);
      EXPECT_MAT_NEAR(d.alphaD(), fdFlat(mb, mbc, q, alpha, tau), 1e-14);
      const auto [dq, da] = numericJacobians(
          mb, q, alpha, [&](const VecX<LD> & qq, const VecX<LD> & aa) { return fdFlat(mb, mbc, qq, aa, tau); });
      EXPECT_MAT_NEAR(d.dalphaDDq(), dq, 1e-8);
      EXPECT_MAT_NEAR(d.dalphaDDalpha(), da, 1e-8);
      // d alphaD / d tau = H^-1: columns of FD differences in tau (FD is affine in tau: exact)
      MatX<LD> dt(mb.nrDof(), mb.nrDof());
      for(int m = 0; m < mb.nrDof(); ++m)
        dt.col(m) = fdFlat(mb, mbc, q, alpha, VecX<LD>(tau + VecX<LD>::Unit(mb.nrDof(), m))) - d.alphaD();
      EXPECT_MAT_NEAR(d.Minv(), dt, 1e-12);
      worstQ = std::max(worstQ, rbdtest::relErr(d.dalphaDDq(), dq));
      worstA = std::max(worstA, rbdtest::relErr(d.dalphaDDalpha(), da));
      worstMinv = std::max(worstMinv, rbdtest::relErr(d.Minv(), dt));
    }
  }
  std::printf("dalphaD/dq vs differences: %.2e, dalphaD/dalpha: %.2e, Minv: %.2e\n", worstQ, worstA, worstMinv);
}

using AD = Eigen::AutoDiffScalar<Eigen::VectorXd>;

/// The runtime's ID in AutoDiffScalar: derivatives of tau along q(δ) = q0 + qdot(q0, δ), then alpha.
TEST(Derivatives, InverseDynamicsMatchesAutoDiff)
{
  rbdtest::Rng rng(1503);
  double worstQ = 0, worstA = 0;
  for(const auto & mb : models(rng))
  {
    const rbd::MultiBodyTpl<AD> mbA = mb.cast<AD>();
    const int nv = mb.nrDof();
    for(int trial = 0; trial < 2; ++trial)
    {
      rbd::MultiBodyConfig mbc = state<double>(rng, mb);
      dyntest::kinematics(mb, mbc);
      rbd::InverseDynamicsDerivatives d(mb);
      d.inverseDynamicsDerivatives(mb, mbc);
      // Seeds: δ (tangent of q, nv) then alpha (nv).
      rbd::MultiBodyConfigTpl<AD> cfg = rbdtest::castInputs<AD>(mbA, mbc);
      const Eigen::VectorXd q0 = dyntest::qOf(mb, mbc);
      VecX<AD> delta(nv), qA(q0.size()), alphaA(nv);
      for(int m = 0; m < nv; ++m) delta(m) = AD(0.0, 2 * nv, m);
      for(Eigen::Index p = 0; p < q0.size(); ++p) qA(p) = AD(q0(p), Eigen::VectorXd::Zero(2 * nv));
      const VecX<AD> qdot = rbd::configurationDerivative<AD>(mbA, qA, delta);
      qA += qdot;
      const Eigen::VectorXd alpha = dyntest::dofOf(mb, mbc.alpha);
      for(int m = 0; m < nv; ++m) alphaA(m) = AD(alpha(m), 2 * nv, nv + m);
      rbd::vectorToParam<AD>(qA, cfg.q);
      rbd::vectorToDof<AD>(alphaA, cfg.alpha);
      dyntest::kinematics(mbA, cfg);
      rbd::InverseDynamicsTpl<AD> id(mbA);
      id.inverseDynamics(mbA, cfg);
      Eigen::MatrixXd dq(nv, nv), da(nv, nv);
      Eigen::VectorXd tau(nv);
      int k = 0;
      for(const auto & joint : cfg.jointTorque)
        for(const AD & t : joint)
        {
          tau(k) = t.value();
          const Eigen::VectorXd g = t.derivatives().size() ? t.derivatives() : Eigen::VectorXd::Zero(2 * nv);
          dq.row(k) = g.head(nv).transpose();
          da.row(k) = g.tail(nv).transpose();
          ++k;
        }
      EXPECT_MAT_NEAR(d.tau(), tau, 1e-12);
      EXPECT_MAT_NEAR(d.dtauDq(), dq, 1e-11);
      EXPECT_MAT_NEAR(d.dtauDalpha(), da, 1e-11);
      worstQ = std::max(worstQ, rbdtest::relErr(d.dtauDq(), dq));
      worstA = std::max(worstA, rbdtest::relErr(d.dtauDalpha(), da));
    }
  }
  std::printf("dtau/dq vs AutoDiff: %.2e, dtau/dalpha: %.2e\n", worstQ, worstA);
}

/// d tau/d alpha at alpha = 0 is zero (Coriolis is quadratic in alpha); at alphaD = 0, gravity 0,
/// no force and alpha = 0, d tau/dq = 0 (tau = 0 everywhere near): closed forms.
TEST(Derivatives, ClosedFormsAtRest)
{
  rbdtest::Rng rng(1504);
  for(const auto & mb : models(rng))
  {
    rbd::MultiBodyConfig mbc(mb);
    rbdtest::randomState<double>(rng, mb, mbc);
    for(auto & a : mbc.alpha)
      for(double & x : a) x = 0;
    dyntest::kinematics(mb, mbc);
    rbd::InverseDynamicsDerivatives d(mb);
    d.inverseDynamicsDerivatives(mb, mbc);
    EXPECT_LE(d.dtauDalpha().cwiseAbs().maxCoeff(), 1e-12);
    for(auto & a : mbc.alphaD)
      for(double & x : a) x = 0;
    mbc.gravity.setZero();
    d.inverseDynamicsDerivatives(mb, mbc);
    EXPECT_LE(d.dtauDq().cwiseAbs().maxCoeff(), 1e-12);
  }
}

} // namespace
