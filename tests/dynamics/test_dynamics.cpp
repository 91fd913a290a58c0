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
  Sample<T> s{dyntest::castModel<T>(dyntest::randomModel(rng, n, 0.3)), {}};
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

/// Error scale of a forward-dynamics solve H alphaD = tau - C in precision eps: a backward-stable
/// method is exact for data perturbed by eps (|H| |alphaD| + |C| + |tau|), so its forward error
/// is at most ~ eps |H^-1| (|H| |alphaD| + |C| + |tau|) (2-norms of H from its eigenvalues,
/// inf-norms of the vectors). units() expresses an error in that scale: the digits lost beyond
/// what the conditioning of the problem dictates.
template<typename T>
struct FdScale
{
  double lambdaMin = 1, lambdaMax = 1, scaleC = 0, scaleTau = 0;
  FdScale(const MatX<T> & H, const VecX<T> & C, const VecX<T> & tau)
  {
    if(H.rows() == 0) return;
    Eigen::SelfAdjointEigenSolver<MatX<T>> eig(H);
    lambdaMin = static_cast<double>(eig.eigenvalues().minCoeff());
    lambdaMax = static_cast<double>(eig.eigenvalues().maxCoeff());
    scaleC = static_cast<double>(C.cwiseAbs().maxCoeff());
    scaleTau = static_cast<double>(tau.cwiseAbs().maxCoeff());
  }
  double cond() const { return lambdaMax / lambdaMin; }
  /// |alphaD - ref| in units of the error scale.
  double units(const VecX<T> & alphaD, const VecX<T> & ref, double eps) const
  {
    if(ref.size() == 0) return 0;
    const double err = static_cast<double>((alphaD - ref).cwiseAbs().maxCoeff());
    return err * lambdaMin / (eps * data(ref));
  }
  /// Backward error |ID(alphaD) - tau| relative to the data (|H| |alphaD| + |C| + |tau|).
  double backward(const VecX<T> & tauBack, const VecX<T> & tau, const VecX<T> & alphaD) const
  {
    if(tau.size() == 0) return 0;
    return static_cast<double>((tauBack - tau).cwiseAbs().maxCoeff()) / data(alphaD);
  }

private:
  double data(const VecX<T> & alphaD) const
  {
    return lambdaMax * static_cast<double>(alphaD.cwiseAbs().maxCoeff()) + scaleC + scaleTau;
  }
};

/// Worst errors of a forward-dynamics algorithm over random trees.
struct FdErrors
{
  double forward = 0;  ///< |alphaD - reference| relative (max(1, |reference|)), for the record
  double units = 0;    ///< the same in units of FdScale
  double backward = 0; ///< FdScale::backward of ID(alphaD)
  template<typename T>
  void update(const FdScale<T> & sc, const VecX<T> & alphaD, const VecX<T> & ref, double eps, double bwd)
  {
    if(ref.size() == 0) return;
    forward = std::max(forward, rbdtest::relErr(alphaD, ref));
    units = std::max(units, sc.units(alphaD, ref, eps));
    backward = std::max(backward, bwd);
  }
};

// The random trees (up to 60 bodies, masses 0.2-3 kg, rotational inertias down to 1e-5 kg m^2,
// lever arms up to tens of metres) have cond(H) up to ~1e9; errors are measured with FdScale.
// CRBA + Cholesky stays within a few units and is backward stable (~eps). ABA loses up to a few
// hundred units (backward error a few thousand eps) on trees where a light body hangs on a heavy
// subtree and I^A - U D^-1 U^T cancels: a property of the algorithm, not of this implementation
// (a plain 6x6-matrix ABA written for comparison shows the same errors, and so does ABA in long
// double relative to its own eps). Any real defect gives errors of order 1e10 units and more.
constexpr double kCrbaUnits = 10, kAbaUnits = 2000;

TYPED_TEST(Dynamics, ForwardDynamicsInvertsInverseDynamics)
{
  using T = TypeParam;
  const double eps = static_cast<double>(std::numeric_limits<T>::epsilon());
  rbdtest::Rng rng(63);
  FdErrors crba, aba;
  double accAba = 0, condMax = 0;
  for(int n : kSizes)
    for(int trial = 0; trial < 4; ++trial)
    {
      auto s = sample<T>(rng, n);
      if(trial % 2 == 1) s.mbc.gravity.setZero();
      rbd::InverseDynamicsTpl<T> id(s.mb);
      rbd::ForwardDynamicsTpl<T> fd(s.mb);
      rbd::ForwardDynamicsABATpl<T> fdAba(s.mb);
      // FD(ID(alphaD)) = alphaD
      const VecX<T> alphaD = dyntest::dofOf(s.mb, s.mbc.alphaD);
      id.inverseDynamics(s.mb, s.mbc);
      const VecX<T> tau = dyntest::dofOf(s.mb, s.mbc.jointTorque);
      auto idOf = [&](const VecX<T> & a) {
        auto c = s.mbc;
        c.alphaD = rbd::vectorToDof(s.mb, a);
        id.inverseDynamics(s.mb, c);
        return dyntest::dofOf(s.mb, c.jointTorque);
      };
      fd.forwardDynamics(s.mb, s.mbc);
      EXPECT_EQ(fd.solver(), rbd::ForwardDynamicsTpl<T>::Solver::LLT);
      const FdScale<T> sc(fd.H(), fd.C(), tau);
      condMax = std::max(condMax, sc.cond());
      const VecX<T> alphaDCrba = dyntest::dofOf(s.mb, s.mbc.alphaD);
      crba.update(sc, alphaDCrba, alphaD, eps, sc.backward(idOf(alphaDCrba), tau, alphaDCrba));
      // ABA on the same torques; its body accelerations against ID's for the same alphaD
      fdAba.forwardDynamics(s.mb, s.mbc);
      const VecX<T> alphaDAba = dyntest::dofOf(s.mb, s.mbc.alphaD);
      aba.update(sc, alphaDAba, alphaD, eps, sc.backward(idOf(alphaDAba), tau, alphaDAba));
      const auto accFromAba = s.mbc.bodyAccB;
      id.inverseDynamics(s.mb, s.mbc);
      for(std::size_t i = 0; i < accFromAba.size(); ++i)
        accAba = std::max(accAba, rbdtest::relErr(accFromAba[i].vector(), s.mbc.bodyAccB[i].vector()));
    }
  EXPECT_LE(crba.units, kCrbaUnits);
  EXPECT_LE(aba.units, kAbaUnits);
  EXPECT_LE(crba.backward, 10 * eps);
  EXPECT_LE(aba.backward, 10 * kAbaUnits * eps);
  EXPECT_LE(accAba, 10 * eps);
  std::printf("[ info ] FD(ID(alphaD)) vs alphaD: CRBA %.2e (%.2g units), ABA %.2e (%.2g units), max cond(H) %.1e\n",
              crba.forward, crba.units, aba.forward, aba.units, condMax);
  std::printf("[ info ] ID(FD(tau)) vs tau, backward error: CRBA %.2e, ABA %.2e; ABA vs ID bodyAccB %.2e\n",
              crba.backward, aba.backward, accAba);
}

// ABA against CRBA directly, with and without gravity and external forces.
TYPED_TEST(Dynamics, ArticulatedBodyMatchesCompositeRigidBody)
{
  using T = TypeParam;
  const double eps = static_cast<double>(std::numeric_limits<T>::epsilon());
  rbdtest::Rng rng(64);
  FdErrors diff;
  for(int n : kSizes)
    for(int trial = 0; trial < 4; ++trial)
    {
      auto s = sample<T>(rng, n, trial < 2);
      if(trial % 2 == 1) s.mbc.gravity.setZero();
      rbd::ForwardDynamicsTpl<T> fd(s.mb);
      fd.forwardDynamics(s.mb, s.mbc);
      const VecX<T> alphaDCrba = dyntest::dofOf(s.mb, s.mbc.alphaD);
      rbd::ForwardDynamicsABATpl<T> aba(s.mb);
      s.mbc.alphaD = rbd::vectorToDof(s.mb, VecX<T>::Zero(s.mb.nrDof()));
      aba.forwardDynamics(s.mb, s.mbc);
      const FdScale<T> sc(fd.H(), fd.C(), dyntest::dofOf(s.mb, s.mbc.jointTorque));
      diff.update(sc, dyntest::dofOf(s.mb, s.mbc.alphaD), alphaDCrba, eps, 0.0);
    }
  EXPECT_LE(diff.units, kAbaUnits + kCrbaUnits);
  std::printf("[ info ] ABA vs CRBA alphaD: %.2e (%.2g units)\n", diff.forward, diff.units);
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

// The double path keeps its digits: double results vs long double on the same inputs. ID, H and
// C are well conditioned (expect ~1e-15); FD and ABA lose what the conditioning dictates (FdScale
// units, double eps), no more.
TEST(DynamicsPrecision, DoubleAgreesWithLongDouble)
{
  const double eps = std::numeric_limits<double>::epsilon();
  rbdtest::Rng rng(66);
  double eTau = 0, eH = 0, eC = 0, condMax = 0;
  FdErrors crba, abaErr;
  for(int n : kSizes)
    for(int trial = 0; trial < 3; ++trial)
    {
      auto s = sample<double>(rng, n);
      const auto mbL = dyntest::castModel<long double>(s.mb);
      auto mbcL = rbdtest::castInputs(mbL, s.mbc);
      dyntest::kinematics(mbL, mbcL);

      rbd::InverseDynamics id(s.mb);
      rbd::InverseDynamicsTpl<long double> idL(mbL);
      id.inverseDynamics(s.mb, s.mbc);
      idL.inverseDynamics(mbL, mbcL);
      eTau = std::max(eTau, rbdtest::relErr(dyntest::dofOf(s.mb, s.mbc.jointTorque),
                                            dyntest::dofOf(mbL, mbcL.jointTorque)));

      rbd::ForwardDynamics fd(s.mb);
      rbd::ForwardDynamicsTpl<long double> fdL(mbL);
      fd.forwardDynamics(s.mb, s.mbc);
      fdL.forwardDynamics(mbL, mbcL);
      if(s.mb.nrDof() == 0) continue;
      eH = std::max(eH, rbdtest::relErr(fd.H(), fdL.H()));
      eC = std::max(eC, rbdtest::relErr(fd.C(), fdL.C()));
      const VecX<double> refL = dyntest::dofOf(mbL, mbcL.alphaD).cast<double>();
      const FdScale<double> sc(fd.H(), fd.C(), dyntest::dofOf(s.mb, s.mbc.jointTorque));
      condMax = std::max(condMax, sc.cond());
      crba.update(sc, dyntest::dofOf(s.mb, s.mbc.alphaD), refL, eps, 0.0);

      rbd::ForwardDynamicsABA aba(s.mb);
      aba.forwardDynamics(s.mb, s.mbc);
      abaErr.update(sc, dyntest::dofOf(s.mb, s.mbc.alphaD), refL, eps, 0.0);
    }
  EXPECT_LE(eTau, 1e-13);
  EXPECT_LE(eH, 1e-13);
  EXPECT_LE(eC, 1e-13);
  EXPECT_LE(crba.units, kCrbaUnits);
  EXPECT_LE(abaErr.units, kAbaUnits);
  std::printf("[ info ] double vs long double: tau %.2e H %.2e C %.2e FD %.2e (%.2g units) ABA %.2e (%.2g units), "
              "max cond(H) %.1e\n",
              eTau, eH, eC, crba.forward, crba.units, abaErr.forward, abaErr.units, condMax);
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
  EXPECT_THROW(id.sInverseDynamics(s.mb, other.mbc), std::domain_error);
  EXPECT_THROW(fd.sForwardDynamics(s.mb, other.mbc), std::domain_error);
  EXPECT_THROW(aba.sForwardDynamics(s.mb, other.mbc), std::domain_error);
  // one wrong vector at a time
  const auto last = static_cast<std::size_t>(s.mb.nrJoints() - 1);
  auto bad = s.mbc;
  bad.alphaD[last].push_back(0);
  EXPECT_THROW(id.sInverseDynamics(s.mb, bad), std::domain_error);
  bad = s.mbc;
  bad.jointTorque[last].push_back(0);
  EXPECT_THROW(fd.sForwardDynamics(s.mb, bad), std::domain_error);
  EXPECT_THROW(aba.sForwardDynamics(s.mb, bad), std::domain_error);
  bad = s.mbc;
  bad.force.pop_back();
  EXPECT_THROW(id.sInverseDynamics(s.mb, bad), std::domain_error);
  EXPECT_THROW(fd.sForwardDynamics(s.mb, bad), std::domain_error);
  EXPECT_THROW(aba.sForwardDynamics(s.mb, bad), std::domain_error);
  bad = s.mbc;
  bad.motionSubspace[last] = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, s.mb.joint(int(last)).dof() + 1);
  EXPECT_THROW(id.sInverseDynamics(s.mb, bad), std::domain_error);
  EXPECT_THROW(fd.sForwardDynamics(s.mb, bad), std::domain_error);
  EXPECT_THROW(aba.sForwardDynamics(s.mb, bad), std::domain_error);
}

} // namespace
