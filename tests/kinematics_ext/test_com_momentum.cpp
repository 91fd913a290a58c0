// CoM, CoM Jacobian, centroidal momentum (matrix) and centroidal ZMP, in double and long double on
// random trees (all joint types, 30% backward joints), against hand computations over the bodies,
// central differences along q ⊕ dq, forwardDynamics (Newton-Euler for the whole system) and
// inverseDynamics (contact wrench of a floating base).

#include <rbd/CoM.h>
#include <rbd/FD.h>
#include <rbd/ID.h>
#include <rbd/Momentum.h>
#include <rbd/ZMP.h>

#include "KinExtTestUtils.h"

namespace
{

template<typename T>
using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
template<typename T>
using MatX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
template<typename T>
using Vec3 = sva::Vector3<T>;

template<typename T>
struct Case
{
  rbd::MultiBodyTpl<T> mb;
  rbd::MultiBodyConfigTpl<T> mbc;
};

/// Random tree with some dof and the given root (random if none), random state, FK + FV done.
template<typename T>
Case<T> randomCase(rbdtest::Rng & rng, int rootType = -1)
{
  rbd::MultiBodyTpl<T> mb;
  do
  {
    const int n = std::uniform_int_distribution<int>(3, 10)(rng);
    const auto root = rootType < 0 ? kinext::randomRoot(rng) : static_cast<rbd::Joint::Type>(rootType);
    mb = kinext::randomModel<T>(rng, n, root);
  } while(mb.nrDof() == 0);
  Case<T> c{mb, rbd::MultiBodyConfigTpl<T>(mb)};
  rbdtest::randomState(rng, c.mb, c.mbc);
  kinext::kin(c.mb, c.mbc);
  return c;
}

template<typename T>
T totalMass(const rbd::MultiBodyTpl<T> & mb)
{
  T M = T(0);
  for(const auto & b : mb.bodies()) M += b.inertia().mass();
  return M;
}

/// CoM of body i in world coordinates, through the sva frame composition xlt(c_i) X_0_i.
template<typename T>
Vec3<T> bodyCoMW(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc, int i)
{
  const auto & I = mb.body(i).inertia();
  const Vec3<T> c = I.momentum() / I.mass();
  return (sva::PTransform<T>(c) * mbc.bodyPosW[static_cast<std::size_t>(i)]).translation();
}

/// Weighted CoM sum_i w_i m_i x_i / M by hand.
template<typename T>
Vec3<T> weightedCoM(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc,
                    const std::vector<T> & w)
{
  Vec3<T> s = Vec3<T>::Zero();
  for(int i = 0; i < mb.nrBodies(); ++i)
    s += w[static_cast<std::size_t>(i)] * mb.body(i).inertia().mass() * bodyCoMW(mb, mbc, i);
  return s / totalMass(mb);
}

/// Copy of mbc with gravity-free body accelerations for its alphaD (or alphaD = 0).
template<typename T>
rbd::MultiBodyConfigTpl<T> withAcc(const rbd::MultiBodyTpl<T> & mb, rbd::MultiBodyConfigTpl<T> mbc,
                                   bool zeroAlphaD = false)
{
  if(zeroAlphaD)
    for(auto & a : mbc.alphaD) std::fill(a.begin(), a.end(), T(0));
  rbd::forwardAcceleration(mb, mbc);
  return mbc;
}

template<typename T>
Vec3<T> comDotOf(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc)
{
  return rbd::computeCoMVelocity(mb, mbc);
}

constexpr int nrCases = 20;

} // namespace

template<typename T>
class CoMMomentumTest : public ::testing::Test
{
};
TYPED_TEST_SUITE(CoMMomentumTest, kinext::Scalars, );

// ------------------------------------------------------------------------------------------------
// CoM

// computeCoM is the mass-weighted mean of the body CoMs placed by FK.
TYPED_TEST(CoMMomentumTest, CoMMatchesHandComputation)
{
  using T = TypeParam;
  rbdtest::Rng rng(21);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    Vec3<T> mc = Vec3<T>::Zero();
    for(int i = 0; i < c.mb.nrBodies(); ++i) mc += c.mb.body(i).inertia().mass() * bodyCoMW(c.mb, c.mbc, i);
    const Vec3<T> expected = mc / totalMass(c.mb);
    EXPECT_MAT_NEAR(rbd::computeCoM(c.mb, c.mbc), expected, kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(rbd::sComputeCoM(c.mb, c.mbc), expected, kinext::Prec<T>::exact);
  }
}

// CoM velocity = central difference of the CoM along q ⊕ alpha t; CoM acceleration (after
// forwardAcceleration, and after inverseDynamics minus gravity) = central difference of the CoM
// velocity along q ⊕ (alpha t + alphaD t²/2).
TYPED_TEST(CoMMomentumTest, CoMVelocityAndAccelerationMatchFiniteDifferences)
{
  using T = TypeParam;
  const T h = T(kinext::Prec<T>::h);
  rbdtest::Rng rng(22);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    const auto p = kinext::along(c.mb, c.mbc, h), m = kinext::along(c.mb, c.mbc, -h);
    const Vec3<T> cdFD = (rbd::computeCoM(c.mb, p) - rbd::computeCoM(c.mb, m)) / (2 * h);
    EXPECT_MAT_NEAR(rbd::computeCoMVelocity(c.mb, c.mbc), cdFD, kinext::Prec<T>::fd);

    const VecX<T> alphaD = rbd::dofToVector(c.mb, c.mbc.alphaD);
    const auto pa = kinext::along(c.mb, c.mbc, h, alphaD), ma = kinext::along(c.mb, c.mbc, -h, alphaD);
    const Vec3<T> cddFD = (rbd::computeCoMVelocity(c.mb, pa) - rbd::computeCoMVelocity(c.mb, ma)) / (2 * h);
    const auto acc = withAcc(c.mb, c.mbc);
    EXPECT_MAT_NEAR(rbd::computeCoMAcceleration(c.mb, acc), cddFD, kinext::Prec<T>::fd);
    EXPECT_MAT_NEAR(rbd::sComputeCoMAcceleration(c.mb, acc), cddFD, kinext::Prec<T>::fd);
    auto id = c.mbc;
    rbd::InverseDynamicsTpl<T>(c.mb).inverseDynamics(c.mb, id); // bodyAccB with [0; gravity]
    EXPECT_MAT_NEAR(Vec3<T>(rbd::computeCoMAcceleration(c.mb, id) - id.gravity), cddFD, kinext::Prec<T>::fd);
  }
}

// CoM Jacobian: columns = central differences of the (weighted) CoM along q ⊕ ±h e_k; J alpha =
// CoM velocity; jacobianDot = central difference of J along q ⊕ alpha t; normalAcceleration =
// Jdot alpha = CoM acceleration for alphaD = 0.
TYPED_TEST(CoMMomentumTest, CoMJacobianMatchesFiniteDifferences)
{
  using T = TypeParam;
  const T h = T(kinext::Prec<T>::h);
  rbdtest::Rng rng(23);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    std::vector<T> w(static_cast<std::size_t>(c.mb.nrBodies()), T(1));
    if(n % 2 == 1)
      for(auto & x : w) x = T(rbdtest::uniform(rng, 0.2, 2.0));
    rbd::CoMJacobianTpl<T> comJac(c.mb, w);
    const MatX<T> J = comJac.jacobian(c.mb, c.mbc);
    ASSERT_EQ(J.rows(), 3);
    ASSERT_EQ(J.cols(), c.mb.nrDof());
    for(int k = 0; k < c.mb.nrDof(); ++k)
    {
      auto p = c.mbc, m = c.mbc;
      p.q = kinext::perturb(c.mb, c.mbc.q, VecX<T>(VecX<T>::Unit(c.mb.nrDof(), k) * h));
      m.q = kinext::perturb(c.mb, c.mbc.q, VecX<T>(VecX<T>::Unit(c.mb.nrDof(), k) * -h));
      rbd::forwardKinematics(c.mb, p);
      rbd::forwardKinematics(c.mb, m);
      EXPECT_MAT_NEAR(VecX<T>(J.col(k)), Vec3<T>((weightedCoM(c.mb, p, w) - weightedCoM(c.mb, m, w)) / (2 * h)),
                      kinext::Prec<T>::fd)
          << "column " << k;
    }
    const VecX<T> alpha = rbd::dofToVector(c.mb, c.mbc.alpha);
    EXPECT_MAT_NEAR(comJac.velocity(c.mb, c.mbc), VecX<T>(J * alpha), kinext::Prec<T>::exact);
    if(n % 2 == 0)
    {
      EXPECT_MAT_NEAR(VecX<T>(J * alpha), rbd::computeCoMVelocity(c.mb, c.mbc), kinext::Prec<T>::exact);
      EXPECT_MAT_NEAR(comJac.normalAcceleration(c.mb, c.mbc),
                      rbd::computeCoMAcceleration(c.mb, withAcc(c.mb, c.mbc, true)), kinext::Prec<T>::exact);
    }
    const auto p = kinext::along(c.mb, c.mbc, h), m = kinext::along(c.mb, c.mbc, -h);
    const MatX<T> Jp = comJac.jacobian(c.mb, p), Jm = comJac.jacobian(c.mb, m);
    const MatX<T> Jd = comJac.jacobianDot(c.mb, c.mbc);
    EXPECT_MAT_NEAR(Jd, MatX<T>((Jp - Jm) / (2 * h)), kinext::Prec<T>::fd);
    EXPECT_MAT_NEAR(comJac.normalAcceleration(c.mb, c.mbc), VecX<T>(Jd * alpha), kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(comJac.sNormalAcceleration(c.mb, c.mbc), VecX<T>(Jd * alpha), kinext::Prec<T>::exact);
  }
}

// ------------------------------------------------------------------------------------------------
// Centroidal momentum

// h_G against the classical sum over bodies: k_G = sum (x_i - c) x m_i xd_i + R_i Ic_i R_i^T w_i,
// l = sum m_i xd_i (Ic_i: rotational inertia about the body CoM, I_O = Ic - m c^ c^); A_g alpha = h_G.
TYPED_TEST(CoMMomentumTest, CentroidalMomentumMatchesSumOverBodies)
{
  using T = TypeParam;
  rbdtest::Rng rng(24);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    const Vec3<T> com = rbd::computeCoM(c.mb, c.mbc);
    Vec3<T> k = Vec3<T>::Zero(), l = Vec3<T>::Zero();
    for(int i = 0; i < c.mb.nrBodies(); ++i)
    {
      const auto & I = c.mb.body(i).inertia();
      const T mass = I.mass();
      const Vec3<T> ci = I.momentum() / mass;
      const sva::Matrix3<T> cx = sva::vector3ToCrossMatrix(ci);
      const sva::Matrix3<T> Ic = I.inertia() + mass * cx * cx;
      const sva::Matrix3<T> R = kinext::R_0(c.mbc, i);
      const auto & vW = c.mbc.bodyVelW[static_cast<std::size_t>(i)];
      const Vec3<T> x = bodyCoMW(c.mb, c.mbc, i);
      const Vec3<T> xd = vW.linear() + vW.angular().cross(Vec3<T>(R * ci));
      k += (x - com).cross(Vec3<T>(mass * xd)) + R * Ic * R.transpose() * vW.angular();
      l += mass * xd;
    }
    Eigen::Matrix<T, 6, 1> expected;
    expected << k, l;
    EXPECT_MAT_NEAR(rbd::computeCentroidalMomentum(c.mb, c.mbc, com).vector(), expected, kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(l, VecX<T>(totalMass(c.mb) * rbd::computeCoMVelocity(c.mb, c.mbc)), kinext::Prec<T>::exact);
    rbd::CentroidalMomentumMatrixTpl<T> cmm(c.mb);
    cmm.computeMatrix(c.mb, c.mbc, com);
    ASSERT_EQ(cmm.matrix().rows(), 6);
    ASSERT_EQ(cmm.matrix().cols(), c.mb.nrDof());
    EXPECT_MAT_NEAR(VecX<T>(cmm.matrix() * rbd::dofToVector(c.mb, c.mbc.alpha)), expected, kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(cmm.momentum(c.mb, c.mbc, com).vector(), expected, kinext::Prec<T>::exact);
  }
}

// d/dt h_G = central difference of h_G(t) (about the moving CoM) along q ⊕ (alpha t + alphaD t²/2);
// matrixDot = central difference of A_g along q ⊕ alpha t; normalMomentumDot = Adot alpha = h_G rate
// for alphaD = 0; weighted matrix: A_w alpha = momentum(), Adot_w alpha = normalMomentumDot().
TYPED_TEST(CoMMomentumTest, MomentumDerivativesMatchFiniteDifferences)
{
  using T = TypeParam;
  const T h = T(kinext::Prec<T>::h);
  rbdtest::Rng rng(25);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    const Vec3<T> com = rbd::computeCoM(c.mb, c.mbc), comDot = comDotOf(c.mb, c.mbc);
    auto hG = [&](const rbd::MultiBodyConfigTpl<T> & mbc) {
      return rbd::computeCentroidalMomentum(c.mb, mbc, rbd::computeCoM(c.mb, mbc)).vector();
    };
    const VecX<T> alphaD = rbd::dofToVector(c.mb, c.mbc.alphaD);
    const VecX<T> hdFD =
        (hG(kinext::along(c.mb, c.mbc, h, alphaD)) - hG(kinext::along(c.mb, c.mbc, -h, alphaD))) / (2 * h);
    const auto hd = rbd::computeCentroidalMomentumDot(c.mb, withAcc(c.mb, c.mbc), com, comDot);
    EXPECT_MAT_NEAR(hd.vector(), hdFD, kinext::Prec<T>::fd);

    std::vector<T> w(static_cast<std::size_t>(c.mb.nrBodies()), T(1));
    if(n % 2 == 1)
      for(auto & x : w) x = T(rbdtest::uniform(rng, 0.2, 2.0));
    rbd::CentroidalMomentumMatrixTpl<T> cmm(c.mb, w);
    const auto p = kinext::along(c.mb, c.mbc, h), m = kinext::along(c.mb, c.mbc, -h);
    cmm.computeMatrix(c.mb, p, rbd::computeCoM(c.mb, p));
    const MatX<T> Ap = cmm.matrix();
    cmm.computeMatrix(c.mb, m, rbd::computeCoM(c.mb, m));
    const MatX<T> Am = cmm.matrix();
    cmm.computeMatrixAndMatrixDot(c.mb, c.mbc, com, comDot);
    const MatX<T> A = cmm.matrix(), Ad = cmm.matrixDot();
    EXPECT_MAT_NEAR(Ad, MatX<T>((Ap - Am) / (2 * h)), kinext::Prec<T>::fd);
    cmm.computeMatrix(c.mb, c.mbc, com);
    cmm.computeMatrixDot(c.mb, c.mbc, com, comDot);
    EXPECT_MAT_NEAR(cmm.matrix(), A, kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(cmm.matrixDot(), Ad, kinext::Prec<T>::exact);

    const VecX<T> alpha = rbd::dofToVector(c.mb, c.mbc.alpha);
    EXPECT_MAT_NEAR(VecX<T>(A * alpha), cmm.momentum(c.mb, c.mbc, com).vector(), kinext::Prec<T>::exact);
    const auto nmd = cmm.normalMomentumDot(c.mb, c.mbc, com, comDot);
    EXPECT_MAT_NEAR(nmd.vector(), VecX<T>(Ad * alpha), kinext::Prec<T>::exact);
    if(n % 2 == 0)
    {
      const auto hd0 = rbd::computeCentroidalMomentumDot(c.mb, withAcc(c.mb, c.mbc, true), com, comDot);
      EXPECT_MAT_NEAR(nmd.vector(), hd0.vector(), kinext::Prec<T>::exact);
    }
  }
}

// Newton-Euler for the whole floating system: with alphaD from forwardDynamics (random joint
// torques, random external forces), d/dt h_G equals the sum of the external wrenches about the CoM:
// gravity (M g at the CoM), mbc.force (world coordinates at the world origin) and the Free root
// joint's torque (a wrench on the root body, in its coordinates).
TYPED_TEST(CoMMomentumTest, MomentumRateEqualsExternalWrench)
{
  using T = TypeParam;
  rbdtest::Rng rng(26);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng, rbd::Joint::Free);
    for(auto & f : c.mbc.force)
      f = sva::ForceVec<T>(rbdtest::randomTransform(rng, 2.).translation().cast<T>(),
                           rbdtest::randomTransform(rng, 5.).translation().cast<T>());
    rbd::ForwardDynamicsTpl<T> fd(c.mb);
    fd.forwardDynamics(c.mb, c.mbc);
    const auto acc = withAcc(c.mb, c.mbc);
    const Vec3<T> com = rbd::computeCoM(c.mb, acc);
    const auto hd = rbd::computeCentroidalMomentumDot(c.mb, acc, com, comDotOf(c.mb, acc));

    Vec3<T> n_G = Vec3<T>::Zero(), f = -totalMass(c.mb) * c.mbc.gravity; // gravity at the CoM
    for(const auto & fe : c.mbc.force)
    {
      n_G += fe.couple() - com.cross(fe.force()); // moved from the world origin to the CoM
      f += fe.force();
    }
    const auto & tau0 = c.mbc.jointTorque[0];
    const sva::Matrix3<T> R = kinext::R_0(c.mbc, 0);
    const Vec3<T> nR = R * Vec3<T>(tau0[0], tau0[1], tau0[2]), fR = R * Vec3<T>(tau0[3], tau0[4], tau0[5]);
    n_G += nR + (c.mbc.bodyPosW[0].translation() - com).cross(fR);
    f += fR;
    Eigen::Matrix<T, 6, 1> expected;
    expected << n_G, f;
    EXPECT_MAT_NEAR(hd.vector(), expected, kinext::Prec<T>::solve);
    EXPECT_MAT_NEAR(Vec3<T>(totalMass(c.mb) * rbd::computeCoMAcceleration(c.mb, acc)), f,
                    kinext::Prec<T>::solve);
  }
}

// ------------------------------------------------------------------------------------------------
// ZMP

// A robot at rest: the ZMP (point-mass and full) is the CoM projected on the plane z = altitude.
TYPED_TEST(CoMMomentumTest, ZMPOfStaticRobotIsCoMProjection)
{
  using T = TypeParam;
  rbdtest::Rng rng(27);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    for(auto & a : c.mbc.alpha) std::fill(a.begin(), a.end(), T(0));
    for(auto & a : c.mbc.alphaD) std::fill(a.begin(), a.end(), T(0));
    kinext::kin(c.mb, c.mbc);
    const auto acc = withAcc(c.mb, c.mbc);
    const Vec3<T> com = rbd::computeCoM(c.mb, acc);
    const T altitude = T(rbdtest::uniform(rng, -1, 1));
    const Vec3<T> expected(com.x(), com.y(), altitude);
    EXPECT_MAT_NEAR(rbd::computeCentroidalZMP(acc, com, rbd::computeCoMAcceleration(c.mb, acc), altitude), expected,
                    kinext::Prec<T>::exact);
    const auto hd = rbd::computeCentroidalMomentumDot(c.mb, acc, com, Vec3<T>(Vec3<T>::Zero()));
    EXPECT_MAT_NEAR(rbd::computeCentroidalZMP(c.mb, acc, com, hd, altitude), expected, kinext::Prec<T>::exact);
  }
}

// A moving floating robot: inverseDynamics gives the wrench the root must receive (the contact
// wrench, there being no other external force). Its moment about the full centroidal ZMP has no
// horizontal component. With the angular momentum rate removed, the full formula reduces to the
// point-mass one.
TYPED_TEST(CoMMomentumTest, ZMPIsZeroHorizontalMomentPointOfContactWrench)
{
  using T = TypeParam;
  rbdtest::Rng rng(28);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng, rbd::Joint::Free);
    auto id = c.mbc;
    rbd::InverseDynamicsTpl<T>(c.mb).inverseDynamics(c.mb, id);
    const auto & tau0 = id.jointTorque[0];
    const sva::Matrix3<T> R = kinext::R_0(c.mbc, 0);
    const Vec3<T> nR = R * Vec3<T>(tau0[0], tau0[1], tau0[2]), fR = R * Vec3<T>(tau0[3], tau0[4], tau0[5]);

    const auto acc = withAcc(c.mb, c.mbc);
    const Vec3<T> com = rbd::computeCoM(c.mb, acc);
    const auto hd = rbd::computeCentroidalMomentumDot(c.mb, acc, com, comDotOf(c.mb, acc));
    const T altitude = T(rbdtest::uniform(rng, -1, 1));
    const Vec3<T> zmp = rbd::computeCentroidalZMP(c.mb, acc, com, hd, altitude);
    EXPECT_EQ(zmp.z(), altitude);
    const Vec3<T> n_p = nR + (c.mbc.bodyPosW[0].translation() - zmp).cross(fR);
    // Rounding scale of the sum: the terms are as large as |n| and |r x f| (r can be long when the
    // vertical force is small, putting the ZMP far away).
    const Vec3<T> r_zmp = c.mbc.bodyPosW[0].translation() - zmp;
    const T scale = std::max(T(1), nR.norm() + fR.norm() + r_zmp.norm() * fR.norm());
    EXPECT_LE(static_cast<double>(std::abs(n_p.x()) / scale), kinext::Prec<T>::exact);
    EXPECT_LE(static_cast<double>(std::abs(n_p.y()) / scale), kinext::Prec<T>::exact);

    const sva::ForceVec<T> linearOnly(Vec3<T>::Zero(), hd.force());
    EXPECT_MAT_NEAR(rbd::computeCentroidalZMP(c.mb, acc, com, linearOnly, altitude),
                    rbd::computeCentroidalZMP(acc, com, Vec3<T>(hd.force() / totalMass(c.mb)), altitude),
                    kinext::Prec<T>::exact);
  }
}

// Checked variants reject a configuration of another model.
TYPED_TEST(CoMMomentumTest, CheckedVariantsThrow)
{
  using T = TypeParam;
  rbdtest::Rng rng(29);
  const auto mb = kinext::randomModel<T>(rng, 6, rbd::Joint::Free);
  const auto other = kinext::randomModel<T>(rng, 4, rbd::Joint::Free);
  rbd::MultiBodyConfigTpl<T> mbc(mb), bad(other);
  kinext::kin(mb, mbc);
  kinext::kin(other, bad);
  EXPECT_NO_THROW(rbd::sComputeCoMVelocity(mb, mbc));
  EXPECT_THROW(rbd::sComputeCoM(mb, bad), std::domain_error);
  EXPECT_THROW(rbd::sComputeCoMVelocity(mb, bad), std::domain_error);
  rbd::CoMJacobianTpl<T> comJac(mb);
  EXPECT_THROW(comJac.sJacobian(mb, bad), std::domain_error);
  EXPECT_THROW(comJac.sJacobianDot(mb, bad), std::domain_error);
  EXPECT_THROW(rbd::CoMJacobianTpl<T>(mb, std::vector<T>(2, T(1))), std::domain_error);
  rbd::CentroidalMomentumMatrixTpl<T> cmm(mb);
  EXPECT_NO_THROW(cmm.sComputeMatrixAndMatrixDot(mb, mbc, Vec3<T>::Zero(), Vec3<T>::Zero()));
  EXPECT_THROW(cmm.sComputeMatrix(mb, bad, Vec3<T>::Zero()), std::domain_error);
}
