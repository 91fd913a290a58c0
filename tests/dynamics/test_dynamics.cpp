// Consistency of the dynamics on random trees (every joint type, both directions, external
// forces): H symmetric positive definite and equal to the kinetic energy form, H columns from ID,
// FD(ID(alphaD)) = alphaD, ABA = CRBA, power balance d(T + V)/dt = alpha.tau + P_ext, double vs
// long double, solver fallback and checked variants.

#include <cstdio>
#include <limits>

#include <Eigen/Eigenvalues>

#include "DynTestUtils.h"

namespace
{

using dyntest::MatX;
using dyntest::VecX;

template<typename T>
class Dynamics : public ::testing::Test
{
};
TYPED_TEST_SUITE(Dynamics, dyntest::Scalars, );

/// A random model in scalar T with a random state, external forces and gravity.
template<typename T>
struct Sample
{
  rbd::MultiBodyTpl<T> mb;
  rbd::MultiBodyConfigTpl<T> mbc;
};

template<typename T>
Sample<T> sample(rbdtest::Rng & rng, int n, bool forces = true)
{
  Sample<T> s{dyntest::randomModel(rng, n, 0.3).template cast<T>(), {}};
  s.mbc = rbd::MultiBodyConfigTpl<T>(s.mb);
  rbdtest::randomState<T>(rng, s.mb, s.mbc);
  if(forces) dyntest::randomForces(rng, s.mbc);
  dyntest::kinematics(s.mb, s.mbc);
  return s;
}

const std::vector<int> kSizes{1, 2, 3, 4, 6, 9, 14, 20, 30, 45, 60};

TYPED_TEST(Dynamics, MassMatrixSymmetricPositiveDefiniteAndKineticEnergy)
{
  using T = TypeParam;
  rbdtest::Rng rng(61);
  double worst = 0;
  for(int n : kSizes)
    for(int trial = 0; trial < 3; ++trial)
    {
      auto s = sample<T>(rng, n);
      rbd::ForwardDynamicsTpl<T> fd(s.mb);
      fd.computeH(s.mb, s.mbc);
      const MatX<T> & H = fd.H();
      EXPECT_EQ(H, H.transpose());
      if(H.rows() == 0) continue;
      Eigen::SelfAdjointEigenSolver<MatX<T>> eig(H);
      EXPECT_GT(eig.eigenvalues().minCoeff(), T(0)) << "n = " << n;
      // T = alpha^T H alpha / 2 = sum_i v_i . I_i v_i / 2
      const VecX<T> alpha = dyntest::dofOf(s.mb, s.mbc.alpha);
      const T ke = dyntest::kineticEnergy(s.mb, s.mbc);
      const double e = rbdtest::relErr(VecX<T>::Constant(1, T(0.5) * alpha.dot(H * alpha)), VecX<T>::Constant(1, ke));
      worst = std::max(worst, e);
    }
  EXPECT_LE(worst, dyntest::tol<T>(1e-12, 1e-15));
  std::printf("[ info ] alpha^T H alpha / 2 vs kinetic energy: %.2e\n", worst);
}

// tau(alphaD) = H alphaD + C is affine: column k of H = ID(e_k) - ID(0), any state.
TYPED_TEST(Dynamics, MassMatrixColumnsFromInverseDynamics)
{
  using T = TypeParam;
  rbdtest::Rng rng(62);
  double worst = 0;
  for(int n : {1, 2, 5, 10, 20})
    for(int trial = 0; trial < 3; ++trial)
    {
      auto s = sample<T>(rng, n);
      rbd::ForwardDynamicsTpl<T> fd(s.mb);
      fd.computeH(s.mb, s.mbc);
      rbd::InverseDynamicsTpl<T> id(s.mb);
      auto tauOf = [&](const VecX<T> & alphaD) {
        s.mbc.alphaD = rbd::vectorToDof(s.mb, alphaD);
        id.inverseDynamics(s.mb, s.mbc);
        return dyntest::dofOf(s.mb, s.mbc.jointTorque);
      };
      const VecX<T> tau0 = tauOf(VecX<T>::Zero(s.mb.nrDof()));
      MatX<T> H(s.mb.nrDof(), s.mb.nrDof());
      for(int k = 0; k < s.mb.nrDof(); ++k) H.col(k) = tauOf(VecX<T>::Unit(s.mb.nrDof(), k)) - tau0;
      if(H.size() == 0) continue;
      worst = std::max(worst, rbdtest::relErr(fd.H(), H));
    }
  EXPECT_LE(worst, dyntest::tol<T>(1e-12, 1e-15));
  std::printf("[ info ] CRBA H vs ID columns: %.2e\n", worst);
}

TYPED_TEST(Dynamics, ForwardDynamicsInvertsInverseDynamics)
{
  using T = TypeParam;
  rbdtest::Rng rng(63);
  double worst = 0;
  for(int n : kSizes)
    for(int trial = 0; trial < 3; ++trial)
    {
      auto s = sample<T>(rng, n);
      const VecX<T> alphaD = dyntest::dofOf(s.mb, s.mbc.alphaD);
      rbd::InverseDynamicsTpl<T> id(s.mb);
      id.inverseDynamics(s.mb, s.mbc);
      rbd::ForwardDynamicsTpl<T> fd(s.mb);
      s.mbc.alphaD = rbd::vectorToDof(s.mb, VecX<T>::Zero(s.mb.nrDof()));
      fd.forwardDynamics(s.mb, s.mbc);
      EXPECT_EQ(fd.solver(), rbd::ForwardDynamicsTpl<T>::Solver::LLT);
      worst = std::max(worst, rbdtest::relErr(dyntest::dofOf(s.mb, s.mbc.alphaD), alphaD));
    }
  EXPECT_LE(worst, dyntest::tol<T>(1e-9, 1e-12));
  std::printf("[ info ] FD(ID(alphaD)) vs alphaD: %.2e\n", worst);
}

// ABA against CRBA (alphaD) and ABA's body accelerations against ID's for the same alphaD.
TYPED_TEST(Dynamics, ArticulatedBodyMatchesCompositeRigidBody)
{
  using T = TypeParam;
  rbdtest::Rng rng(64);
  double worstAlphaD = 0, worstAcc = 0;
  for(int n : kSizes)
    for(int trial = 0; trial < 4; ++trial)
    {
      auto s = sample<T>(rng, n);
      if(trial % 2 == 1) s.mbc.gravity.setZero();
      rbd::ForwardDynamicsTpl<T> fd(s.mb);
      fd.forwardDynamics(s.mb, s.mbc);
      const VecX<T> alphaDCrba = dyntest::dofOf(s.mb, s.mbc.alphaD);
      rbd::ForwardDynamicsABATpl<T> aba(s.mb);
      s.mbc.alphaD = rbd::vectorToDof(s.mb, VecX<T>::Zero(s.mb.nrDof()));
      aba.forwardDynamics(s.mb, s.mbc);
      worstAlphaD = std::max(worstAlphaD, rbdtest::relErr(dyntest::dofOf(s.mb, s.mbc.alphaD), alphaDCrba));
      const auto accAba = s.mbc.bodyAccB;
      rbd::InverseDynamicsTpl<T> id(s.mb);
      id.inverseDynamics(s.mb, s.mbc);
      for(std::size_t i = 0; i < accAba.size(); ++i)
        worstAcc = std::max(worstAcc, rbdtest::relErr(accAba[i].vector(), s.mbc.bodyAccB[i].vector()));
    }
  EXPECT_LE(worstAlphaD, dyntest::tol<T>(1e-9, 1e-12));
  EXPECT_LE(worstAcc, dyntest::tol<T>(1e-10, 1e-13));
  std::printf("[ info ] ABA vs CRBA alphaD: %.2e, bodyAccB: %.2e\n", worstAlphaD, worstAcc);
}

// d(T + V)/dt along (q ⊕ alpha t, alpha + alphaD t) = alpha . tau + sum_i f_ext_i . v_i, with
// tau = ID(alphaD); energies from FK/FV and the body inertias only, derivative by differences.
TYPED_TEST(Dynamics, PowerBalance)
{
  using T = TypeParam;
  rbdtest::Rng rng(65);
  double worst = 0;
  for(int n : {1, 2, 3, 5, 8, 13, 21, 30})
    for(int trial = 0; trial < 4; ++trial)
    {
      auto s = sample<T>(rng, n);
      if(trial % 2 == 0) s.mbc.gravity.setZero();
      const auto & mb = s.mb;
      rbd::InverseDynamicsTpl<T> id(mb);
      id.inverseDynamics(mb, s.mbc);
      const VecX<T> q = dyntest::qOf(mb, s.mbc), alpha = dyntest::dofOf(mb, s.mbc.alpha),
                    alphaD = dyntest::dofOf(mb, s.mbc.alphaD);
      T power = alpha.dot(dyntest::dofOf(mb, s.mbc.jointTorque));
      for(std::size_t i = 0; i < s.mbc.force.size(); ++i)
        power += s.mbc.force[i].dot(s.mbc.bodyPosW[i].invMul(s.mbc.bodyVelB[i])); // world coordinates
      auto energy = [&](T t) {
        rbd::MultiBodyConfigTpl<T> c = s.mbc;
        c.q = rbd::vectorToParam(mb, rbd::integrateConfiguration(mb, q, VecX<T>(alpha * t)));
        c.alpha = rbd::vectorToDof(mb, VecX<T>(alpha + alphaD * t));
        dyntest::kinematics(mb, c);
        return dyntest::kineticEnergy(mb, c) + dyntest::potentialEnergy(mb, c);
      };
      const T dEdt = dyntest::derivative<T>(energy, T(1e-3) / (T(1) + alpha.cwiseAbs().sum()));
      worst = std::max(worst, rbdtest::relErr(VecX<T>::Constant(1, power), VecX<T>::Constant(1, dEdt)));
    }
  EXPECT_LE(worst, dyntest::tol<T>(1e-8, 1e-11));
  std::printf("[ info ] power balance: %.2e\n", worst);
}

// The double path keeps its digits: double results vs long double on the same inputs.
TEST(DynamicsPrecision, DoubleAgreesWithLongDouble)
{
  rbdtest::Rng rng(66);
  double eTau = 0, eH = 0, eC = 0, eFd = 0, eAba = 0;
  for(int n : kSizes)
    for(int trial = 0; trial < 3; ++trial)
    {
      auto s = sample<double>(rng, n);
      const auto mbL = s.mb.cast<long double>();
      auto mbcL = rbdtest::castInputs(mbL, s.mbc);
      dyntest::kinematics(mbL, mbcL);

      rbd::InverseDynamics id(s.mb);
      rbd::InverseDynamicsTpl<long double> idL(mbL);
      id.inverseDynamics(s.mb, s.mbc);
      idL.inverseDynamics(mbL, mbcL);
      eTau = std::max(eTau, rbdtest::relErr(dyntest::dofOf(s.mb, s.mbc.jointTorque), dyntest::dofOf(mbL, mbcL.jointTorque)));

      rbd::ForwardDynamics fd(s.mb);
      rbd::ForwardDynamicsTpl<long double> fdL(mbL);
      fd.forwardDynamics(s.mb, s.mbc);
      fdL.forwardDynamics(mbL, mbcL);
      if(s.mb.nrDof() == 0) continue;
      eH = std::max(eH, rbdtest::relErr(fd.H(), fdL.H()));
      eC = std::max(eC, rbdtest::relErr(fd.C(), fdL.C()));
      eFd = std::max(eFd, rbdtest::relErr(dyntest::dofOf(s.mb, s.mbc.alphaD), dyntest::dofOf(mbL, mbcL.alphaD)));

      rbd::ForwardDynamicsABA aba(s.mb);
      rbd::ForwardDynamicsABATpl<long double> abaL(mbL);
      aba.forwardDynamics(s.mb, s.mbc);
      abaL.forwardDynamics(mbL, mbcL);
      eAba = std::max(eAba, rbdtest::relErr(dyntest::dofOf(s.mb, s.mbc.alphaD), dyntest::dofOf(mbL, mbcL.alphaD)));
    }
  EXPECT_LE(eTau, 1e-12);
  EXPECT_LE(eH, 1e-12);
  EXPECT_LE(eC, 1e-12);
  EXPECT_LE(eFd, 1e-10);
  EXPECT_LE(eAba, 1e-10);
  std::printf("[ info ] double vs long double: tau %.2e H %.2e C %.2e FD %.2e ABA %.2e\n", eTau, eH, eC, eFd, eAba);
}

// ---------------------------------------------------------------------------------------------
// Degenerate models: the FD solve policy and ABA's refusal.

/// base --Rev--> heavy --Rev--> massless (a zero inertia: H has a zero row and column).
rbd::MultiBody masslessLeaf()
{
  rbd::MultiBodyGraph g;
  rbdtest::Rng rng(67);
  g.addBody(rbd::Body(rbdtest::randomInertia(rng), "base"));
  g.addBody(rbd::Body(rbdtest::randomInertia(rng), "heavy"));
  g.addBody(rbd::Body(0.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero(), "massless"));
  g.addJoint(rbd::Joint(rbd::Joint::Rev, Eigen::Vector3d::UnitX(), true, "j1"));
  g.addJoint(rbd::Joint(rbd::Joint::Rev, Eigen::Vector3d::UnitY(), true, "j2"));
  g.linkBodies("base", rbdtest::randomTransform(rng), "heavy", sva::PTransformd::Identity(), "j1");
  g.linkBodies("heavy", rbdtest::randomTransform(rng), "massless", sva::PTransformd::Identity(), "j2");
  return g.makeMultiBody("base", rbd::Joint::Fixed);
}

TEST(DynamicsDegenerate, ForwardDynamicsFallsBackToLDLT)
{
  const auto mb = masslessLeaf();
  rbd::MultiBodyConfig mbc(mb);
  rbdtest::Rng rng(68);
  rbdtest::randomState(rng, mb, mbc);
  mbc.jointTorque[2] = {0.0};
  dyntest::kinematics(mb, mbc);
  rbd::ForwardDynamics fd(mb);
  fd.forwardDynamics(mb, mbc);
  EXPECT_EQ(fd.solver(), rbd::ForwardDynamics::Solver::LDLT);
  // j1 sees a single rigid body: alphaD_1 = (tau_1 - C_1) / H_11; the free massless joint gets 0
  EXPECT_NEAR(mbc.alphaD[1][0], (mbc.jointTorque[1][0] - fd.C()(0)) / fd.H()(0, 0), 1e-12);
  EXPECT_EQ(mbc.alphaD[2][0], 0.0);
  EXPECT_EQ(fd.H()(1, 1), 0.0);

  rbd::ForwardDynamicsABA aba(mb);
  EXPECT_THROW(aba.forwardDynamics(mb, mbc), std::runtime_error);
}

TEST(DynamicsDegenerate, NonFiniteInputsThrow)
{
  rbdtest::Rng rng(69);
  auto s = sample<double>(rng, 6);
  int j = 0;
  while(j < s.mb.nrJoints() && s.mb.joint(j).dof() == 0) ++j;
  ASSERT_LT(j, s.mb.nrJoints());
  s.mbc.jointTorque[static_cast<std::size_t>(j)][0] = std::numeric_limits<double>::quiet_NaN();
  rbd::ForwardDynamics fd(s.mb);
  EXPECT_THROW(fd.forwardDynamics(s.mb, s.mbc), std::runtime_error);
  rbd::ForwardDynamicsABA aba(s.mb);
  EXPECT_THROW(aba.forwardDynamics(s.mb, s.mbc), std::runtime_error);
}

// ---------------------------------------------------------------------------------------------
// Checked variants.

TEST(DynamicsChecked, ThrowOnWrongSizes)
{
  rbdtest::Rng rng(70);
  auto s = sample<double>(rng, 8);
  auto other = sample<double>(rng, 5);
  rbd::InverseDynamics id(s.mb);
  rbd::ForwardDynamics fd(s.mb);
  rbd::ForwardDynamicsABA aba(s.mb);
  EXPECT_NO_THROW(id.sInverseDynamics(s.mb, s.mbc));
  EXPECT_NO_THROW(fd.sForwardDynamics(s.mb, s.mbc));
  EXPECT_NO_THROW(aba.sForwardDynamics(s.mb, s.mbc));
  // a config of another model
  EXPECT_THROW(id.sInverseDynamics(s.mb, other.mbc), std::invalid_argument);
  EXPECT_THROW(fd.sForwardDynamics(s.mb, other.mbc), std::invalid_argument);
  EXPECT_THROW(aba.sForwardDynamics(s.mb, other.mbc), std::invalid_argument);
  // one wrong vector at a time
  const auto last = static_cast<std::size_t>(s.mb.nrJoints() - 1);
  auto bad = s.mbc;
  bad.alphaD[last].push_back(0);
  EXPECT_THROW(id.sInverseDynamics(s.mb, bad), std::invalid_argument);
  bad = s.mbc;
  bad.jointTorque[last].push_back(0);
  EXPECT_THROW(fd.sForwardDynamics(s.mb, bad), std::invalid_argument);
  EXPECT_THROW(aba.sForwardDynamics(s.mb, bad), std::invalid_argument);
  bad = s.mbc;
  bad.force.pop_back();
  EXPECT_THROW(id.sInverseDynamics(s.mb, bad), std::invalid_argument);
  EXPECT_THROW(fd.sForwardDynamics(s.mb, bad), std::invalid_argument);
  EXPECT_THROW(aba.sForwardDynamics(s.mb, bad), std::invalid_argument);
  bad = s.mbc;
  bad.motionSubspace[last] = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, s.mb.joint(int(last)).dof() + 1);
  EXPECT_THROW(id.sInverseDynamics(s.mb, bad), std::invalid_argument);
  EXPECT_THROW(fd.sForwardDynamics(s.mb, bad), std::invalid_argument);
  EXPECT_THROW(aba.sForwardDynamics(s.mb, bad), std::invalid_argument);
}

} // namespace
