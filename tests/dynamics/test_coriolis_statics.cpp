// Coriolis matrix and inverse statics (RBDyn's Coriolis, InverseStatics) on random trees with every
// joint type and backward joints:
// - C alpha equals the velocity terms of inverse dynamics (RNEA at alphaD = 0, no gravity, no force);
// - Mdot - 2C is skew-symmetric, Mdot from Richardson differences of the mass matrix along
//   q ⊕ alpha t, in long double;
// - inverse statics equals inverse dynamics at zero velocity and acceleration;
// - its torque Jacobian equals Richardson differences of the static torques along q ⊕ h e_m (forces
//   constant in the world), and with q-dependent forces f_k(q) = f0_k + B_k q plus RBDyn's
//   jacMomentsAndForces term (jac_k = -B_k).
#include <gtest/gtest.h>

#include <rbd/Coriolis.h>
#include <rbd/InverseStatics.h>

#include "DynTestUtils.h"

namespace
{

using LD = long double;
using dyntest::MatX;
using dyntest::VecX;

/// A copy of mbc at q ⊕ dq (flat tangent step), FK and FV run.
template<typename T>
rbd::MultiBodyConfigTpl<T> moved(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc, const VecX<T> & dq)
{
  rbd::MultiBodyConfigTpl<T> out = mbc;
  out.q = rbd::vectorToParam(mb, rbd::integrateConfiguration(mb, dyntest::qOf(mb, mbc), dq));
  dyntest::kinematics(mb, out);
  return out;
}

TEST(Coriolis, ProductIsTheVelocityTermsAndMdotMinus2CIsSkew)
{
  rbdtest::Rng rng(81);
  for(int n = 0; n < 8; ++n)
  {
    const rbd::MultiBody mb = dyntest::randomModel(rng, 4 + n % 5);
    const auto mbL = dyntest::castModel<LD>(mb);
    rbd::MultiBodyConfig mbc(mb);
    rbdtest::randomState(rng, mb, mbc);
    mbc.gravity.setZero();
    auto mbcL = rbdtest::castInputs(mbL, mbc);
    dyntest::kinematics(mbL, mbcL);
    dyntest::kinematics(mb, mbc);

    rbd::CoriolisTpl<LD> coriolis(mbL);
    const MatX<LD> C = coriolis.coriolis(mbL, mbcL);
    const VecX<LD> alpha = dyntest::dofOf(mbL, mbcL.alpha);
    rbd::InverseDynamicsTpl<LD> id(mbL);
    VecX<LD> N(mbL.nrDof());
    id.nonLinearEffects(mbL, mbcL, N);
    EXPECT_MAT_NEAR(VecX<LD>(C * alpha), N, 1e-15);

    rbd::ForwardDynamicsTpl<LD> fd(mbL);
    auto massMatrix = [&](LD t) {
      const auto at = moved<LD>(mbL, mbcL, VecX<LD>(alpha * t));
      fd.computeH(mbL, at);
      return MatX<LD>(fd.H());
    };
    const MatX<LD> S = dyntest::derivative<LD>(massMatrix, 1e-4L) - 2 * C;
    EXPECT_MAT_NEAR(MatX<LD>(S + S.transpose()), MatX<LD>::Zero(S.rows(), S.cols()), 1e-11); // C: ~1e1

    // the double instantiation agrees with long double
    rbd::Coriolis coriolisD(mb);
    EXPECT_MAT_NEAR(coriolisD.coriolis(mb, mbc), C, 1e-12);
  }
}

TEST(InverseStatics, TorquesAreInverseDynamicsAtRest)
{
  rbdtest::Rng rng(82);
  for(int n = 0; n < 8; ++n)
  {
    const rbd::MultiBody mb = dyntest::randomModel(rng, 4 + n % 5);
    rbd::MultiBodyConfig mbc(mb);
    rbdtest::randomState(rng, mb, mbc);
    dyntest::randomForces(rng, mbc);
    mbc.alpha = rbd::vectorToDof(mb, Eigen::VectorXd::Zero(mb.nrDof()));
    mbc.alphaD = mbc.alpha;
    dyntest::kinematics(mb, mbc);
    rbd::MultiBodyConfig byId = mbc;
    rbd::InverseDynamics id(mb);
    id.inverseDynamics(mb, byId);
    rbd::InverseStatics is(mb);
    is.sInverseStatics(mb, mbc);
    EXPECT_MAT_NEAR(dyntest::dofOf(mb, mbc.jointTorque), dyntest::dofOf(mb, byId.jointTorque), 1e-13);
    for(int i = 0; i < mb.nrBodies(); ++i)
    {
      EXPECT_MAT_NEAR(is.f()[static_cast<std::size_t>(i)].vector(), id.f()[static_cast<std::size_t>(i)].vector(), 1e-13);
      EXPECT_MAT_NEAR(mbc.bodyAccB[static_cast<std::size_t>(i)].vector(), byId.bodyAccB[static_cast<std::size_t>(i)].vector(),
                      1e-13);
    }
    rbd::MultiBodyConfig wrong = mbc;
    wrong.force.pop_back();
    EXPECT_THROW(is.sInverseStatics(mb, wrong), std::domain_error);
  }
}

/// Static torques (flat) at q ⊕ dq with the forces given by forceAt(q flat).
template<typename ForceAt>
VecX<LD> staticTorques(const rbd::MultiBodyTpl<LD> & mb, const rbd::MultiBodyConfigTpl<LD> & mbc, const VecX<LD> & dq,
                       ForceAt forceAt)
{
  auto at = moved(mb, mbc, dq);
  forceAt(dyntest::qOf(mb, at), at.force);
  rbd::InverseStaticsTpl<LD> is(mb);
  is.inverseStatics(mb, at);
  return dyntest::dofOf(mb, at.jointTorque);
}

/// [jointTorqueDiff()[0]; jointTorqueDiff()[1]; ...] (nrDof x nrDof)
MatX<LD> stacked(const rbd::MultiBodyTpl<LD> & mb, const rbd::InverseStaticsTpl<LD> & is)
{
  MatX<LD> D(mb.nrDof(), mb.nrDof());
  for(int i = 0; i < mb.nrJoints(); ++i)
    D.middleRows(mb.jointPosInDof(i), mb.joint(i).dof()) = is.jointTorqueDiff()[static_cast<std::size_t>(i)];
  return D;
}

TEST(InverseStatics, TorqueJacobianMatchesFiniteDifferences)
{
  rbdtest::Rng rng(83);
  for(int n = 0; n < 6; ++n)
  {
    const auto mbL = dyntest::castModel<LD>(dyntest::randomModel(rng, 4 + n % 4));
    rbd::MultiBodyConfigTpl<LD> mbc(mbL);
    rbdtest::randomState(rng, mbL, mbc);
    dyntest::randomForces(rng, mbc);
    dyntest::kinematics(mbL, mbc);
    rbd::InverseStaticsTpl<LD> is(mbL);
    is.computeTorqueJacobianJoint(mbL, mbc);
    const auto constant = [](const VecX<LD> &, std::vector<sva::ForceVec<LD>> &) {};
    MatX<LD> expected(mbL.nrDof(), mbL.nrDof());
    for(int m = 0; m < mbL.nrDof(); ++m)
      expected.col(m) = dyntest::derivative<LD>(
          [&](LD h) { return staticTorques(mbL, mbc, VecX<LD>(VecX<LD>::Unit(mbL.nrDof(), m) * h), constant); }, 1e-3L);
    EXPECT_MAT_NEAR(stacked(mbL, is), expected, 1e-10);
  }
}

// Forces depending on q (revolute chain: q ⊕ dq = q + dq): f_k(q) = f0_k + B_k q, jac_k = -B_k.
TEST(InverseStatics, TorqueJacobianWithForceJacobians)
{
  rbdtest::Rng rng(84);
  rbdtest::RandomTreeOptions opt;
  opt.types = {rbd::Joint::Rev};
  const auto mbL = dyntest::castModel<LD>(rbdtest::randomGraph(rng, 5, opt).makeMultiBody("b0", true));
  rbd::MultiBodyConfigTpl<LD> mbc(mbL);
  rbdtest::randomState(rng, mbL, mbc);
  dyntest::randomForces(rng, mbc);
  dyntest::kinematics(mbL, mbc);
  const std::vector<sva::ForceVec<LD>> f0 = mbc.force;
  std::vector<MatX<LD>> B, jac;
  for(int i = 0; i < mbL.nrBodies(); ++i)
  {
    B.push_back(MatX<LD>::Random(6, mbL.nrDof()));
    jac.push_back(i == 2 ? MatX<LD>() : MatX<LD>(-B.back())); // an empty matrix: no force derivative
  }
  B[2].setZero();
  const auto forceAt = [&](const VecX<LD> & q, std::vector<sva::ForceVec<LD>> & f) {
    for(std::size_t k = 0; k < f.size(); ++k) f[k] = sva::ForceVec<LD>(Eigen::Matrix<LD, 6, 1>(f0[k].vector() + B[k] * q));
  };
  forceAt(dyntest::qOf(mbL, mbc), mbc.force);
  rbd::InverseStaticsTpl<LD> is(mbL);
  is.computeTorqueJacobianJoint(mbL, mbc, jac);
  MatX<LD> expected(mbL.nrDof(), mbL.nrDof());
  for(int m = 0; m < mbL.nrDof(); ++m)
    expected.col(m) = dyntest::derivative<LD>(
        [&](LD h) { return staticTorques(mbL, mbc, VecX<LD>(VecX<LD>::Unit(mbL.nrDof(), m) * h), forceAt); }, 1e-3L);
  EXPECT_MAT_NEAR(stacked(mbL, is), expected, 1e-10);
}

} // namespace
