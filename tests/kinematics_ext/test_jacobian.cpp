// Jacobian: against forwardVelocity, finite differences of FK along q ⊕ dq, forwardAcceleration and
// a closed-form planar arm. Every test runs in double and long double on random trees (all joint
// types, 30% backward joints, random root joint).

#include <rbd/Jacobian.h>

#include "KinExtTestUtils.h"

namespace
{

template<typename T>
using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
template<typename T>
using MatX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

template<typename T>
struct Case
{
  rbd::MultiBodyTpl<T> mb;
  rbd::MultiBodyConfigTpl<T> mbc;
  std::string body;
  int bodyIndex;
  sva::Vector3<T> point;
};

/// Random tree (with some dof), random state (FK + FV done), random body and point.
template<typename T>
Case<T> randomCase(rbdtest::Rng & rng)
{
  int n = 0;
  rbd::MultiBodyTpl<T> mb;
  do
  {
    n = std::uniform_int_distribution<int>(3, 10)(rng);
    mb = kinext::randomModel<T>(rng, n, kinext::randomRoot(rng));
  } while(mb.nrDof() == 0);
  Case<T> c{mb, {}, "", 0, {}};
  c.mbc = rbd::MultiBodyConfigTpl<T>(c.mb);
  rbdtest::randomState(rng, c.mb, c.mbc);
  kinext::kin(c.mb, c.mbc);
  // a body with at least one dof on its path (a zero-dof Jacobian has its own test)
  do
  {
    c.bodyIndex = std::uniform_int_distribution<int>(0, n - 1)(rng);
    c.body = c.mb.body(c.bodyIndex).name();
  } while(rbd::JacobianTpl<T>(c.mb, c.body).dof() == 0);
  c.point = rbdtest::randomTransform(rng, 0.3).translation().cast<T>();
  return c;
}

/// alpha of the joints on the path, concatenated (the compact Jacobian's column order).
template<typename T>
VecX<T> pathAlpha(const rbd::JacobianTpl<T> & jac, const rbd::MultiBodyConfigTpl<T> & mbc)
{
  VecX<T> a(jac.dof());
  Eigen::Index pos = 0;
  for(int j : jac.jointsPath())
    for(T x : mbc.alpha[static_cast<std::size_t>(j)]) a(pos++) = x;
  return a;
}

/// World position of the body point.
template<typename T>
sva::Vector3<T> pointW(const Case<T> & c, const rbd::MultiBodyConfigTpl<T> & mbc)
{
  return mbc.bodyPosW[static_cast<std::size_t>(c.bodyIndex)].translation() + kinext::R_0(mbc, c.bodyIndex) * c.point;
}

constexpr int nrCases = 20;

} // namespace

template<typename T>
class JacobianTest : public ::testing::Test
{
};
TYPED_TEST_SUITE(JacobianTest, kinext::Scalars, );

// J alpha equals the body velocity of forwardVelocity carried to the point; same for the body
// Jacobian, an arbitrary frame, velocity()/bodyVelocity() and the full Jacobian.
TYPED_TEST(JacobianTest, VelocityMatchesForwardVelocity)
{
  using T = TypeParam;
  rbdtest::Rng rng(11);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    rbd::JacobianTpl<T> jac(c.mb, c.body, c.point);
    const auto b = static_cast<std::size_t>(c.bodyIndex);
    const VecX<T> alpha = pathAlpha(jac, c.mbc);
    // world-aligned: [w_W; v_W + w_W x (R point)]
    const auto & vW = c.mbc.bodyVelW[b];
    const sva::Vector3<T> w = vW.angular();
    Eigen::Matrix<T, 6, 1> expected;
    expected << w, vW.linear() + w.cross(kinext::R_0(c.mbc, c.bodyIndex) * c.point);
    EXPECT_MAT_NEAR(VecX<T>(jac.jacobian(c.mb, c.mbc) * alpha), expected, kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(jac.velocity(c.mb, c.mbc).vector(), expected, kinext::Prec<T>::exact);
    MatX<T> full;
    jac.fullJacobian(c.mb, jac.jacobian(c.mb, c.mbc), full);
    EXPECT_MAT_NEAR(VecX<T>(full * rbd::dofToVector(c.mb, c.mbc.alpha)), expected, kinext::Prec<T>::exact);
    // body axes: [w_B; v_B + w_B x point]
    const auto & vB = c.mbc.bodyVelB[b];
    Eigen::Matrix<T, 6, 1> expectedB;
    expectedB << vB.angular(), vB.linear() + vB.angular().cross(c.point);
    EXPECT_MAT_NEAR(VecX<T>(jac.bodyJacobian(c.mb, c.mbc) * alpha), expectedB, kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(jac.bodyVelocity(c.mb, c.mbc).vector(), expectedB, kinext::Prec<T>::exact);
    // arbitrary frame p: X_0_p applied to the velocity in world coordinates at the world origin
    const sva::PTransform<T> X_0_p = rbdtest::randomTransform(rng).cast<T>();
    const sva::MotionVec<T> v0(w, vW.linear() - w.cross(c.mbc.bodyPosW[b].translation())); // v_O - w x r
    EXPECT_MAT_NEAR(VecX<T>(jac.jacobian(c.mb, c.mbc, X_0_p) * alpha), (X_0_p * v0).vector(),
                    kinext::Prec<T>::exact);
  }
}

// Each column of the full Jacobian (world and body), of the vector Jacobians, equals the central
// difference of FK along q ⊕ (±h e_k); columns of joints off the path come out zero.
TYPED_TEST(JacobianTest, ColumnsMatchFiniteDifferences)
{
  using T = TypeParam;
  const T h = T(kinext::Prec<T>::h);
  rbdtest::Rng rng(12);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    rbd::JacobianTpl<T> jac(c.mb, c.body, c.point);
    const sva::Vector3<T> vec = rbdtest::randomUnit(rng).cast<T>();
    MatX<T> J, JB, JV, JBV;
    jac.fullJacobian(c.mb, jac.jacobian(c.mb, c.mbc), J);
    jac.fullJacobian(c.mb, jac.bodyJacobian(c.mb, c.mbc), JB);
    jac.fullJacobian(c.mb, jac.vectorJacobian(c.mb, c.mbc, vec), JV);
    jac.fullJacobian(c.mb, jac.vectorBodyJacobian(c.mb, c.mbc, vec), JBV);
    const sva::Matrix3<T> R0 = kinext::R_0(c.mbc, c.bodyIndex);
    for(int k = 0; k < c.mb.nrDof(); ++k)
    {
      auto p = c.mbc, m = c.mbc;
      p.q = kinext::perturb(c.mb, c.mbc.q, VecX<T>(VecX<T>::Unit(c.mb.nrDof(), k) * h));
      m.q = kinext::perturb(c.mb, c.mbc.q, VecX<T>(VecX<T>::Unit(c.mb.nrDof(), k) * -h));
      rbd::forwardKinematics(c.mb, p);
      rbd::forwardKinematics(c.mb, m);
      const sva::Matrix3<T> Rd = (kinext::R_0(p, c.bodyIndex) - kinext::R_0(m, c.bodyIndex)) / (2 * h);
      const sva::Vector3<T> pd = (pointW(c, p) - pointW(c, m)) / (2 * h);
      // world: w^ = Rd R^T; body: w_B^ = R^T Rd
      Eigen::Matrix<T, 6, 1> col, colB;
      col << kinext::vee<T>(Rd * R0.transpose()), pd;
      colB << kinext::vee<T>(R0.transpose() * Rd), R0.transpose() * pd;
      EXPECT_MAT_NEAR(VecX<T>(J.col(k)), col, kinext::Prec<T>::fd) << "column " << k;
      EXPECT_MAT_NEAR(VecX<T>(JB.col(k)), colB, kinext::Prec<T>::fd) << "column " << k;
      // linear rows: d/dt (R vec), and the same in body coordinates; angular rows zero
      const sva::Vector3<T> ud = Rd * vec;
      Eigen::Matrix<T, 6, 1> colV, colBV;
      colV << sva::Vector3<T>::Zero(), ud;
      colBV << sva::Vector3<T>::Zero(), R0.transpose() * ud;
      EXPECT_MAT_NEAR(VecX<T>(JV.col(k)), colV, kinext::Prec<T>::fd) << "column " << k;
      EXPECT_MAT_NEAR(VecX<T>(JBV.col(k)), colBV, kinext::Prec<T>::fd) << "column " << k;
    }
  }
}

// jacobianDot / bodyJacobianDot equal the central difference of the Jacobian along q ⊕ alpha t.
TYPED_TEST(JacobianTest, JacobianDotMatchesFiniteDifference)
{
  using T = TypeParam;
  const T h = T(kinext::Prec<T>::h);
  rbdtest::Rng rng(13);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    rbd::JacobianTpl<T> jac(c.mb, c.body, c.point);
    const auto p = kinext::along(c.mb, c.mbc, h), m = kinext::along(c.mb, c.mbc, -h);
    const MatX<T> Jp = jac.jacobian(c.mb, p), Jm = jac.jacobian(c.mb, m);
    const MatX<T> JBp = jac.bodyJacobian(c.mb, p), JBm = jac.bodyJacobian(c.mb, m);
    EXPECT_MAT_NEAR(jac.jacobianDot(c.mb, c.mbc), MatX<T>((Jp - Jm) / (2 * h)), kinext::Prec<T>::fd);
    EXPECT_MAT_NEAR(jac.bodyJacobianDot(c.mb, c.mbc), MatX<T>((JBp - JBm) / (2 * h)), kinext::Prec<T>::fd);
  }
}

// Jdot alpha three ways (jacobianDot, the path sum, forwardAcceleration with alphaD = 0), and the
// point acceleration J alphaD + Jdot alpha against the central difference of the point velocity
// along q(t) = q ⊕ (alpha t + alphaD t²/2), alpha(t) = alpha + alphaD t.
TYPED_TEST(JacobianTest, NormalAccelerationAndPointAcceleration)
{
  using T = TypeParam;
  const T h = T(kinext::Prec<T>::h);
  rbdtest::Rng rng(14);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    rbd::JacobianTpl<T> jac(c.mb, c.body, c.point);
    const VecX<T> alpha = pathAlpha(jac, c.mbc);
    // body accelerations for alphaD = 0 from forwardAcceleration
    auto z = c.mbc;
    for(auto & a : z.alphaD) std::fill(a.begin(), a.end(), T(0));
    rbd::forwardAcceleration(c.mb, z);
    const auto na = jac.normalAcceleration(c.mb, c.mbc);
    EXPECT_MAT_NEAR(na.vector(), VecX<T>(jac.jacobianDot(c.mb, c.mbc) * alpha), kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(na.vector(), jac.normalAcceleration(c.mb, c.mbc, z.bodyAccB).vector(), kinext::Prec<T>::exact);
    const auto naB = jac.bodyNormalAcceleration(c.mb, c.mbc);
    EXPECT_MAT_NEAR(naB.vector(), VecX<T>(jac.bodyJacobianDot(c.mb, c.mbc) * alpha), kinext::Prec<T>::exact);
    EXPECT_MAT_NEAR(naB.vector(), jac.bodyNormalAcceleration(c.mb, c.mbc, z.bodyAccB).vector(),
                    kinext::Prec<T>::exact);
    std::vector<sva::MotionVec<T>> normalAccB;
    rbd::computeNormalAccB(c.mb, c.mbc, normalAccB);
    for(std::size_t i = 0; i < normalAccB.size(); ++i)
      EXPECT_MAT_NEAR(normalAccB[i].vector(), z.bodyAccB[i].vector(), kinext::Prec<T>::exact);

    // d/dt (J alpha) = J alphaD + Jdot alpha
    const VecX<T> alphaD = rbd::dofToVector(c.mb, c.mbc.alphaD);
    VecX<T> alphaDPath(jac.dof());
    Eigen::Index pos = 0;
    for(int j : jac.jointsPath())
      for(T x : c.mbc.alphaD[static_cast<std::size_t>(j)]) alphaDPath(pos++) = x;
    const auto p = kinext::along(c.mb, c.mbc, h, alphaD), m = kinext::along(c.mb, c.mbc, -h, alphaD);
    const VecX<T> accFD = (jac.velocity(c.mb, p).vector() - jac.velocity(c.mb, m).vector()) / (2 * h);
    EXPECT_MAT_NEAR(VecX<T>(jac.jacobian(c.mb, c.mbc) * alphaDPath + na.vector()), accFD, kinext::Prec<T>::fd);
    const VecX<T> accBFD = (jac.bodyVelocity(c.mb, p).vector() - jac.bodyVelocity(c.mb, m).vector()) / (2 * h);
    EXPECT_MAT_NEAR(VecX<T>(jac.bodyJacobian(c.mb, c.mbc) * alphaDPath + naB.vector()), accBFD,
                    kinext::Prec<T>::fd);
  }
}

// translateJacobian / translateBodyJacobian by an offset in body coordinates (RBDyn: the world
// Jacobian's offset is rotated with mbc) from p1 to p2 equal the Jacobian built at p2.
TYPED_TEST(JacobianTest, TranslateJacobianEqualsJacobianAtTranslatedPoint)
{
  using T = TypeParam;
  rbdtest::Rng rng(15);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    const sva::Vector3<T> p2 = rbdtest::randomTransform(rng, 0.5).translation().cast<T>();
    rbd::JacobianTpl<T> jac1(c.mb, c.body, c.point), jac2(c.mb, c.body, p2);
    MatX<T> res;
    jac1.translateBodyJacobian(jac1.bodyJacobian(c.mb, c.mbc), c.mbc, p2 - c.point, res);
    EXPECT_MAT_NEAR(res, jac2.bodyJacobian(c.mb, c.mbc), kinext::Prec<T>::exact);
    jac1.translateJacobian(jac1.jacobian(c.mb, c.mbc), c.mbc, p2 - c.point, res);
    EXPECT_MAT_NEAR(res, jac2.jacobian(c.mb, c.mbc), kinext::Prec<T>::exact);
  }
}

// jointsPath is the root -> body chain; fullJacobian puts each block at jointPosInDof, zero elsewhere.
TYPED_TEST(JacobianTest, JointsPathAndFullJacobianPlacement)
{
  using T = TypeParam;
  rbdtest::Rng rng(16);
  for(int n = 0; n < nrCases; ++n)
  {
    auto c = randomCase<T>(rng);
    rbd::JacobianTpl<T> jac(c.mb, c.body, c.point);
    const auto & path = jac.jointsPath();
    ASSERT_FALSE(path.empty());
    EXPECT_EQ(path.front(), 0);
    EXPECT_EQ(path.back(), c.bodyIndex);
    int dof = 0;
    for(std::size_t k = 0; k < path.size(); ++k)
    {
      if(k > 0)
      {
        EXPECT_EQ(c.mb.parent(path[k]), path[k - 1]);
      }
      dof += c.mb.joint(path[k]).dof();
    }
    EXPECT_EQ(jac.dof(), dof);
    const MatX<T> J = jac.jacobian(c.mb, c.mbc);
    MatX<T> full;
    jac.fullJacobian(c.mb, J, full);
    ASSERT_EQ(full.rows(), 6);
    ASSERT_EQ(full.cols(), c.mb.nrDof());
    std::vector<bool> onPath(static_cast<std::size_t>(c.mb.nrDof()), false);
    int col = 0;
    for(int j : path)
      for(int d = 0; d < c.mb.joint(j).dof(); ++d, ++col)
      {
        onPath[static_cast<std::size_t>(c.mb.jointPosInDof(j) + d)] = true;
        EXPECT_EQ(VecX<T>(full.col(c.mb.jointPosInDof(j) + d)), VecX<T>(J.col(col)));
      }
    for(int k = 0; k < c.mb.nrDof(); ++k)
    {
      if(!onPath[static_cast<std::size_t>(k)])
      {
        EXPECT_TRUE(full.col(k).isZero(0)) << "column " << k;
      }
    }
  }
}

// A body welded to the world (Fixed root): empty Jacobian, zero full Jacobian, zero velocity.
TYPED_TEST(JacobianTest, ZeroDofPath)
{
  using T = TypeParam;
  rbdtest::Rng rng(19);
  const auto mb = kinext::randomModel<T>(rng, 5, rbd::Joint::Fixed);
  rbd::MultiBodyConfigTpl<T> mbc(mb);
  rbdtest::randomState(rng, mb, mbc);
  kinext::kin(mb, mbc);
  rbd::JacobianTpl<T> jac(mb, mb.body(0).name(), sva::Vector3<T>(T(0.1), T(0.2), T(0.3)));
  EXPECT_EQ(jac.dof(), 0);
  EXPECT_EQ(jac.jacobian(mb, mbc).cols(), 0);
  EXPECT_EQ(jac.jacobianDot(mb, mbc).cols(), 0);
  MatX<T> full;
  jac.fullJacobian(mb, jac.jacobian(mb, mbc), full);
  ASSERT_EQ(full.rows(), 6);
  ASSERT_EQ(full.cols(), mb.nrDof());
  EXPECT_TRUE(full.isZero(0));
  EXPECT_TRUE(jac.velocity(mb, mbc).vector().isZero(0));
  EXPECT_TRUE(jac.normalAcceleration(mb, mbc).vector().isZero(0));
}

// Two-link planar arm in closed form:
//
//   world --j1 (Rev z)-- b1 --[l1 along x]-- j2 (Rev z) -- b2 --[l2 along x]-- point
//
// p = (l1 c1 + l2 c12, l1 s1 + l2 s12, 0),  J_xy = [-l1 s1 - l2 s12, -l2 s12; l1 c1 + l2 c12, l2 c12],
// J_wz = [1, 1], Jdot alpha = -(l1 c1 q1d² + l2 c12 (q1d + q2d)², l1 s1 q1d² + l2 s12 (q1d + q2d)²).
TYPED_TEST(JacobianTest, PlanarArmClosedForm)
{
  using T = TypeParam;
  const double l1 = 0.7, l2 = 0.4;
  rbd::MultiBodyGraph mbg;
  const sva::RBInertiad I(1., Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  mbg.addBody(rbd::Body(I, "b0"));
  mbg.addBody(rbd::Body(I, "b1"));
  mbg.addBody(rbd::Body(I, "b2"));
  mbg.addJoint(rbd::Joint(rbd::Joint::Rev, Eigen::Vector3d::UnitZ(), true, "j1"));
  mbg.addJoint(rbd::Joint(rbd::Joint::Rev, Eigen::Vector3d::UnitZ(), true, "j2"));
  mbg.linkBodies("b0", sva::PTransformd::Identity(), "b1", sva::PTransformd::Identity(), "j1");
  mbg.linkBodies("b1", sva::PTransformd(Eigen::Vector3d(l1, 0, 0)), "b2", sva::PTransformd::Identity(), "j2");
  const auto mb = mbg.makeMultiBody("b0", true).template cast<T>();
  rbd::MultiBodyConfigTpl<T> mbc(mb);
  rbd::JacobianTpl<T> jac(mb, "b2", sva::Vector3<T>(T(l2), 0, 0));
  ASSERT_EQ(jac.dof(), 2);
  rbdtest::Rng rng(17);
  for(int n = 0; n < 10; ++n)
  {
    rbdtest::randomState(rng, mb, mbc);
    kinext::kin(mb, mbc);
    using std::cos;
    using std::sin;
    const auto j1 = static_cast<std::size_t>(mb.jointIndexByName("j1"));
    const auto j2 = static_cast<std::size_t>(mb.jointIndexByName("j2"));
    const T q1 = mbc.q[j1][0], q2 = mbc.q[j2][0], a1 = mbc.alpha[j1][0], a2 = mbc.alpha[j2][0];
    const T c1 = cos(q1), s1 = sin(q1), c12 = cos(q1 + q2), s12 = sin(q1 + q2);
    MatX<T> expected = MatX<T>::Zero(6, 2);
    expected(2, 0) = expected(2, 1) = T(1);
    expected(3, 0) = -T(l1) * s1 - T(l2) * s12;
    expected(3, 1) = -T(l2) * s12;
    expected(4, 0) = T(l1) * c1 + T(l2) * c12;
    expected(4, 1) = T(l2) * c12;
    EXPECT_MAT_NEAR(jac.jacobian(mb, mbc), expected, kinext::Prec<T>::exact);
    const T w12 = a1 + a2;
    Eigen::Matrix<T, 6, 1> na = Eigen::Matrix<T, 6, 1>::Zero();
    na(3) = -(T(l1) * c1 * a1 * a1 + T(l2) * c12 * w12 * w12);
    na(4) = -(T(l1) * s1 * a1 * a1 + T(l2) * s12 * w12 * w12);
    EXPECT_MAT_NEAR(jac.normalAcceleration(mb, mbc).vector(), na, kinext::Prec<T>::exact);
  }
}

// Checked variants reject a configuration or a compact Jacobian of the wrong size.
TYPED_TEST(JacobianTest, CheckedVariantsThrow)
{
  using T = TypeParam;
  rbdtest::Rng rng(18);
  const auto mb = kinext::randomModel<T>(rng, 6, rbd::Joint::Free);
  const auto other = kinext::randomModel<T>(rng, 4, rbd::Joint::Fixed);
  rbd::MultiBodyConfigTpl<T> mbc(mb), bad(other);
  kinext::kin(mb, mbc);
  kinext::kin(other, bad);
  rbd::JacobianTpl<T> jac(mb, "b5");
  EXPECT_NO_THROW(jac.sJacobian(mb, mbc));
  EXPECT_NO_THROW(jac.sJacobianDot(mb, mbc));
  EXPECT_THROW(jac.sJacobian(mb, bad), std::domain_error);
  EXPECT_THROW(jac.sBodyJacobianDot(mb, bad), std::domain_error);
  EXPECT_THROW(jac.sVectorJacobian(mb, bad, sva::Vector3<T>::UnitX()), std::domain_error);
  MatX<T> res;
  EXPECT_THROW(jac.sFullJacobian(mb, MatX<T>::Zero(6, jac.dof() + 1), res), std::domain_error);
  EXPECT_THROW(jac.sTranslateJacobian(MatX<T>::Zero(3, jac.dof()), mbc, sva::Vector3<T>::Zero(), res),
               std::domain_error);
  EXPECT_THROW(rbd::JacobianTpl<T>(mb, "no_such_body"), std::out_of_range);
}
