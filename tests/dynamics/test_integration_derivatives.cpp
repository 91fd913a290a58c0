// Derivatives of configuration integration (rbd/IntegrationDerivatives.h) against long double
// central differences with one Richardson step, on the models with every joint type in both
// directions (Fixed, Free and Planar roots) and random trees; first configurationDifference, the
// inverse of ⊕ the other checks compare configurations with, against integrateConfiguration.
//
// Tolerances (long double, eps = 1.1e-19; rotations up to |w| = 3, translations up to 1):
//  - configurationDifference(q, q ⊕ d) = d: a log after an exp, each a few ulps of |d| ≤ 3.5;
//    atan2 and the V(ω)⁻¹ coefficient condition it by at most ~1/sin(θ/2) near θ = π, and
//    |ω| ≤ 3 keeps that under 1.1: bound 1e-16 relative to max(1, |d|).
//  - Derivatives by differences: truncation O(h⁴ f⁽⁵⁾) with h = 1e-3 and derivatives of order 1
//    (1e-12), round-off eps·|q|/h ≈ 1e-16: bound 1e-11 relative to max(1, |D|); the measured
//    worst is printed.

#include <Eigen/Core>

#include <rbd/IntegrationDerivatives.h>

#include "DynTestUtils.h"

namespace
{

using dyntest::MatX;
using dyntest::VecX;
using LD = long double;

std::vector<rbd::MultiBody> models(rbdtest::Rng & rng)
{
  std::vector<rbd::MultiBody> out;
  for(auto & r : dyntest::allJointsModels(rng)) out.push_back(r.mb);
  for(int n : {3, 7, 12}) out.push_back(dyntest::randomModel(rng, n, 0.4));
  out.push_back(dyntest::randomModel(rng, 9, 0.3, true));
  return out;
}

/// Random q with unit quaternions (long double), entries of the vector joints in [-2, 2].
VecX<LD> randomQ(rbdtest::Rng & rng, const rbd::MultiBodyTpl<LD> & mb)
{
  VecX<LD> q(mb.nrParams());
  for(Eigen::Index i = 0; i < q.size(); ++i) q[i] = LD(rbdtest::uniform(rng, -2, 2));
  for(int j = 0; j < mb.nrJoints(); ++j)
  {
    const auto t = mb.joint(j).type();
    if(t != rbd::Joint::Spherical && t != rbd::Joint::Free) continue;
    auto quat = q.segment<4>(mb.jointPosInParam(j));
    quat /= quat.norm();
  }
  return q;
}

/// A tangent vector whose rotations have norm `angle` exactly (a random direction) and whose other
/// entries are uniform in [-scale, scale].
VecX<LD> randomTangent(rbdtest::Rng & rng, const rbd::MultiBodyTpl<LD> & mb, double angle, double scale)
{
  VecX<LD> d(mb.nrDof());
  for(Eigen::Index i = 0; i < d.size(); ++i) d[i] = LD(rbdtest::uniform(rng, -scale, scale));
  for(int j = 0; j < mb.nrJoints(); ++j)
  {
    const auto t = mb.joint(j).type();
    const int v = mb.jointPosInDof(j);
    if(t == rbd::Joint::Spherical || t == rbd::Joint::Free)
      d.segment<3>(v) = (rbdtest::randomUnit(rng) * angle).cast<LD>();
    else if(t == rbd::Joint::Planar || t == rbd::Joint::Rev)
      d[v] = LD(angle * (rbdtest::uniform(rng, 0, 1) < 0.5 ? -1 : 1));
  }
  return d;
}

// Rotation sizes: 0, around the series/closed-form switches (1e-2 of the log, 0.5 of the
// derivative coefficients), typical steps (1e-3) and large ones (3 < π).
const double kAngles[] = {0.0, 1e-9, 1e-3, 9.9e-3, 1.01e-2, 0.3, 0.4999, 0.5001, 1.2, 3.0};

TEST(IntegrationDerivatives, DifferenceInvertsIntegration)
{
  rbdtest::Rng rng(11);
  double worst = 0, worstBack = 0;
  for(const rbd::MultiBody & mbd : models(rng))
  {
    const rbd::MultiBodyTpl<LD> mb = dyntest::castModel<LD>(mbd);
    for(double angle : kAngles)
      for(int trial = 0; trial < 3; ++trial)
      {
        const VecX<LD> q = randomQ(rng, mb), d = randomTangent(rng, mb, angle, 1.0);
        const VecX<LD> q1 = rbd::integrateConfiguration(mb, q, d);
        const VecX<LD> back = rbd::configurationDifference(mb, q, q1);
        const double e = rbdtest::relErr(back, d);
        worst = std::max(worst, e);
        EXPECT_LT(e, 1e-16) << "angle " << angle;
        // and the other way round: q ⊕ (q1 ⊖ q) = q1 (quaternions up to sign)
        const VecX<LD> q2 = rbd::integrateConfiguration(mb, q, back);
        EXPECT_LT(static_cast<double>(rbd::configurationDifference(mb, q1, q2).cwiseAbs().maxCoeff()), 1e-17);
        worstBack = std::max(worstBack, rbdtest::relErr(rbd::configurationDifference(mb, q1, q2), VecX<LD>::Zero(d.size())));
      }
    // the difference of a configuration with itself is 0, also with a negated quaternion
    VecX<LD> q = randomQ(rng, mb), qn = q;
    for(int j = 0; j < mb.nrJoints(); ++j)
    {
      const auto t = mb.joint(j).type();
      if(t == rbd::Joint::Spherical || t == rbd::Joint::Free) qn.segment<4>(mb.jointPosInParam(j)) *= -1;
    }
    EXPECT_LT(static_cast<double>(rbd::configurationDifference(mb, q, q).cwiseAbs().maxCoeff()), 1e-18);
    EXPECT_LT(static_cast<double>(rbd::configurationDifference(mb, q, qn).cwiseAbs().maxCoeff()), 1e-18);
  }
  std::cout << "[ measured ] configurationDifference(q, q ⊕ d) - d: " << worst << "; q ⊕ (q1 ⊖ q) vs q1: " << worstBack
            << "\n";
}

TEST(IntegrationDerivatives, MatchLongDoubleDifferences)
{
  rbdtest::Rng rng(12);
  const LD h = 1e-3L;
  double worstQ = 0, worstW = 0;
  for(const rbd::MultiBody & mbd : models(rng))
  {
    const rbd::MultiBodyTpl<LD> mb = dyntest::castModel<LD>(mbd);
    const int nv = mb.nrDof();
    for(double angle : kAngles)
    {
      const VecX<LD> q = randomQ(rng, mb), w = randomTangent(rng, mb, angle, 1.0);
      const VecX<LD> qp = rbd::integrateConfiguration(mb, q, w);
      const auto D = rbd::integrateConfigurationDerivatives(mb, w);
      MatX<LD> nq(nv, nv), nw(nv, nv);
      for(int k = 0; k < nv; ++k)
      {
        const VecX<LD> e = VecX<LD>::Unit(nv, k);
        nq.col(k) = dyntest::derivative(
            [&](LD t) {
              const VecX<LD> qt = rbd::integrateConfiguration(mb, q, VecX<LD>(e * t));
              return rbd::configurationDifference(mb, qp, rbd::integrateConfiguration(mb, qt, w));
            },
            h);
        nw.col(k) = dyntest::derivative(
            [&](LD t) { return rbd::configurationDifference(mb, qp, rbd::integrateConfiguration(mb, q, VecX<LD>(w + e * t))); },
            h);
      }
      const double eq = rbdtest::relErr(D.dq, nq), ew = rbdtest::relErr(D.dw, nw);
      worstQ = std::max(worstQ, eq);
      worstW = std::max(worstW, ew);
      EXPECT_LT(eq, 1e-11) << "angle " << angle;
      EXPECT_LT(ew, 1e-11) << "angle " << angle;
    }
  }
  std::cout << "[ measured ] d(q ⊕ w)/dq " << worstQ << ", d(q ⊕ w)/dw " << worstW << " vs long double differences\n";
}

// At w = 0 the derivatives are the identity; the double and long double evaluations agree.
TEST(IntegrationDerivatives, IdentityAtZeroAndDoubleAgrees)
{
  rbdtest::Rng rng(13);
  double worst = 0;
  for(const rbd::MultiBody & mb : models(rng))
  {
    const int nv = mb.nrDof();
    const auto D0 = rbd::integrateConfigurationDerivatives(mb, Eigen::VectorXd(Eigen::VectorXd::Zero(nv)));
    EXPECT_EQ(D0.dq, Eigen::MatrixXd::Identity(nv, nv));
    EXPECT_EQ(D0.dw, Eigen::MatrixXd::Identity(nv, nv));
    const rbd::MultiBodyTpl<LD> mbl = dyntest::castModel<LD>(mb);
    for(double angle : kAngles)
    {
      const VecX<LD> w = randomTangent(rng, mbl, angle, 1.0);
      const auto Dl = rbd::integrateConfigurationDerivatives(mbl, w);
      const auto Dd = rbd::integrateConfigurationDerivatives(mb, Eigen::VectorXd(w.cast<double>()));
      worst = std::max({worst, rbdtest::relErr(Dd.dq, Dl.dq), rbdtest::relErr(Dd.dw, Dl.dw)});
    }
  }
  // a few ulps of double per entry (|entries| ≤ ~4)
  EXPECT_LT(worst, 1e-14);
  std::cout << "[ measured ] integration derivatives, double vs long double: " << worst << "\n";
}

// The maps of q as a vector of R^nq (the RK4 step): P = d(q ⊕ δ)/dδ, N = d(n(y) ⊖ ...)/dy, the
// Jacobians of configurationDerivative, against differences; N P = 1.
TEST(IntegrationDerivatives, AmbientMapsMatchDifferences)
{
  rbdtest::Rng rng(14);
  const LD h = 1e-3L;
  double worst[4] = {0, 0, 0, 0};
  for(const rbd::MultiBody & mbd : models(rng))
  {
    const rbd::MultiBodyTpl<LD> mb = dyntest::castModel<LD>(mbd);
    const int nv = mb.nrDof(), nq = mb.nrParams();
    for(int trial = 0; trial < 3; ++trial)
    {
      const VecX<LD> q = randomQ(rng, mb), alpha = randomTangent(rng, mb, 1.3, 2.0);
      // y: q with its quaternions scaled by 0.7 (a stage configuration of RK4 is not unit)
      VecX<LD> y = q;
      for(int j = 0; j < mb.nrJoints(); ++j)
      {
        const auto t = mb.joint(j).type();
        if(t == rbd::Joint::Spherical || t == rbd::Joint::Free) y.segment<4>(mb.jointPosInParam(j)) *= 0.7L;
      }
      const MatX<LD> P = rbd::configurationTangentMap(mb, q), N = rbd::configurationTangentProjection(mb, y);
      const auto C = rbd::configurationDerivativeJacobians(mb, y, alpha);
      MatX<LD> nP(nq, nv), nN(nv, nq), nCq(nq, nq), nCa(nq, nv);
      VecX<LD> yn = y;
      for(int j = 0; j < mb.nrJoints(); ++j)
      {
        const auto t = mb.joint(j).type();
        if(t == rbd::Joint::Spherical || t == rbd::Joint::Free)
          yn.segment<4>(mb.jointPosInParam(j)) /= yn.segment<4>(mb.jointPosInParam(j)).norm();
      }
      for(int k = 0; k < nv; ++k)
      {
        const VecX<LD> e = VecX<LD>::Unit(nv, k);
        nP.col(k) = dyntest::derivative([&](LD t) { return rbd::integrateConfiguration(mb, q, VecX<LD>(e * t)); }, h);
        nCa.col(k) = dyntest::derivative([&](LD t) { return rbd::configurationDerivative(mb, y, VecX<LD>(alpha + e * t)); }, h);
      }
      for(int k = 0; k < nq; ++k)
      {
        const VecX<LD> e = VecX<LD>::Unit(nq, k);
        // n(y + e t) as the runtime reads it: differences taken from n(y)
        nN.col(k) = dyntest::derivative([&](LD t) { return rbd::configurationDifference(mb, yn, VecX<LD>(y + e * t)); }, h);
        nCq.col(k) = dyntest::derivative([&](LD t) { return rbd::configurationDerivative(mb, VecX<LD>(y + e * t), alpha); }, h);
      }
      const double e[4] = {rbdtest::relErr(P, nP), rbdtest::relErr(N, nN), rbdtest::relErr(C.dq, nCq),
                           rbdtest::relErr(C.dalpha, nCa)};
      for(int i = 0; i < 4; ++i)
      {
        worst[i] = std::max(worst[i], e[i]);
        EXPECT_LT(e[i], 1e-11) << "map " << i;
      }
      EXPECT_LT(rbdtest::relErr(MatX<LD>(rbd::configurationTangentProjection(mb, q) * P), MatX<LD>::Identity(nv, nv)), 1e-18);
    }
  }
  std::cout << "[ measured ] tangent map P " << worst[0] << ", projection N " << worst[1] << ", d qdot/dq " << worst[2]
            << ", d qdot/dalpha " << worst[3] << " vs long double differences\n";
}

} // namespace
