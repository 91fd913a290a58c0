// SpaceVecAlg's API beyond Featherstone's tables: the 6xN (vectorised) cross / crossDual / mul /
// invMul / dualMul / transMul with an output argument, the half products angularMul ... forceTransMul,
// ImpedanceVec / AdmittanceVec, and SO3RightJacInv / SO3RightJacInvDot. References: the 6x6
// matrices of SvaTestUtils.h built by hand, the closed-form right Jacobian of SO(3), and central
// differences in long double.
#include <gtest/gtest.h>

#include <sva/SpaceVecAlg.h>

#include "SvaTestUtils.h"

using namespace svatest;

template<class T>
class SvaApi : public ::testing::Test
{
};
TYPED_TEST_SUITE(SvaApi, Scalars, );

template<class T>
using Mat6N = Eigen::Matrix<T, 6, Eigen::Dynamic>;

// Each vectorised product equals the hand-built 6x6 matrix times the 6xN matrix, also when the
// result is the input (aliasing) and for N = 0.
TYPED_TEST(SvaApi, VectorisedProductsMatchTheirMatrices)
{
  using T = TypeParam;
  Rand<T> rnd(11);
  const Vec6<T> v = rnd.vec6();
  const sva::MotionVec<T> mv(v);
  const Mat3<T> E = rnd.quat().toRotationMatrix();
  const Vec3<T> r = rnd.vec3();
  const sva::PTransform<T> X(E, r);
  const T m = T(2.5);
  const Vec3<T> h = rnd.vec3();
  auto spd = [&rnd]() {
    const Mat3<T> A = rnd.mat3();
    return Mat3<T>(A * A.transpose() + Mat3<T>::Identity());
  };
  const Mat3<T> I = spd();
  const sva::RBInertia<T> rbi(m, h, I);
  const Mat3<T> Ma = spd(), H = rnd.mat3(), Ia = spd();
  const sva::ABInertia<T> abi(Ma, H, Ia);
  for(int n : {0, 1, 5})
  {
    const Mat6N<T> M = rnd.mat6N(n);
    Mat6N<T> R(6, n);
    mv.cross(M, R);
    EXPECT_TRUE(near(R, Mat6N<T>(crm<T>(v) * M)));
    mv.crossDual(M, R);
    EXPECT_TRUE(near(R, Mat6N<T>(crf<T>(v) * M)));
    rbi.mul(M, R);
    EXPECT_TRUE(near(R, Mat6N<T>(rbiMatrix<T>(m, h, I) * M)));
    abi.mul(M, R);
    EXPECT_TRUE(near(R, Mat6N<T>(abiMatrix<T>(Ma, H, Ia) * M)));
    X.mul(M, R);
    EXPECT_TRUE(near(R, Mat6N<T>(plxMotion<T>(E, r) * M)));
    X.invMul(M, R);
    EXPECT_TRUE(near(R, Mat6N<T>(plxMotion<T>(E, r).inverse() * M)));
    X.dualMul(M, R);
    EXPECT_TRUE(near(R, Mat6N<T>(plxForce<T>(E, r) * M)));
    X.transMul(M, R);
    EXPECT_TRUE(near(R, Mat6N<T>(plxMotion<T>(E, r).transpose() * M)));
    // aliasing: the result written over the input
    Mat6N<T> A = M;
    mv.cross(A, A);
    EXPECT_TRUE(near(A, Mat6N<T>(crm<T>(v) * M)));
    A = M;
    rbi.mul(A, A);
    EXPECT_TRUE(near(A, Mat6N<T>(rbiMatrix<T>(m, h, I) * M)));
  }
  // the 3-row views
  const Mat6N<T> M = rnd.mat6N(3);
  EXPECT_TRUE(M.topRows(3) == sva::motionAngular(M));
  EXPECT_TRUE(M.bottomRows(3) == sva::motionLinear(M));
  EXPECT_TRUE(M.topRows(3) == sva::forceCouple(M));
  EXPECT_TRUE(M.bottomRows(3) == sva::forceForce(M));
  // into a block of a larger matrix
  Eigen::Matrix<T, 6, 4> big = Eigen::Matrix<T, 6, 4>::Zero();
  const Mat6N<T> M2 = rnd.mat6N(2);
  mv.cross(M2, big.middleCols(1, 2));
  EXPECT_TRUE(near(Mat6N<T>(big.middleCols(1, 2)), Mat6N<T>(crm<T>(v) * M2)));
  EXPECT_EQ(big.col(0), Vec6<T>::Zero());
}

// angularMul ... forceTransMul are the halves of the full products.
TYPED_TEST(SvaApi, HalfProducts)
{
  using T = TypeParam;
  Rand<T> rnd(12);
  const sva::PTransform<T> X(Mat3<T>(rnd.quat().toRotationMatrix()), rnd.vec3());
  const sva::MotionVec<T> mv(rnd.vec6());
  const sva::ForceVec<T> fv(rnd.vec6());
  const Vec6<T> Xv = plxMotion<T>(X.rotation(), X.translation()) * mv.vector();
  const Vec6<T> Xiv = plxMotion<T>(X.rotation(), X.translation()).inverse() * mv.vector();
  const Vec6<T> Xsf = plxForce<T>(X.rotation(), X.translation()) * fv.vector();
  const Vec6<T> Xtf = plxMotion<T>(X.rotation(), X.translation()).transpose() * fv.vector();
  EXPECT_TRUE(near(X.angularMul(mv), Vec3<T>(Xv.template head<3>())));
  EXPECT_TRUE(near(X.linearMul(mv), Vec3<T>(Xv.template tail<3>())));
  EXPECT_TRUE(near(X.angularInvMul(mv), Vec3<T>(Xiv.template head<3>())));
  EXPECT_TRUE(near(X.linearInvMul(mv), Vec3<T>(Xiv.template tail<3>())));
  EXPECT_TRUE(near(X.coupleDualMul(fv), Vec3<T>(Xsf.template head<3>())));
  EXPECT_TRUE(near(X.forceDualMul(fv), Vec3<T>(Xsf.template tail<3>())));
  EXPECT_TRUE(near(X.coupleTransMul(fv), Vec3<T>(Xtf.template head<3>())));
  EXPECT_TRUE(near(X.forceTransMul(fv), Vec3<T>(Xtf.template tail<3>())));
}

// Impedance maps motion to force, admittance force to motion, both diagonally; reciprocal
// coefficients undo each other.
TYPED_TEST(SvaApi, ImpedanceAndAdmittance)
{
  using T = TypeParam;
  Rand<T> rnd(13);
  const Vec6<T> z = rnd.vec6() + Vec6<T>::Constant(T(2));
  const sva::ImpedanceVec<T> Z(z);
  const sva::AdmittanceVec<T> A(Vec6<T>(z.cwiseInverse()));
  const sva::MotionVec<T> v(rnd.vec6());
  const sva::ForceVec<T> f = Z * v;
  EXPECT_TRUE(near(f.vector(), Vec6<T>(z.asDiagonal() * v.vector())));
  EXPECT_TRUE(near((A * f).vector(), v.vector()));
  EXPECT_EQ((v * Z).vector(), f.vector());
  EXPECT_EQ((f * A).vector(), (A * f).vector());
  // homogeneous constructor, arithmetic
  const sva::ImpedanceVec<T> H(T(2), T(3));
  EXPECT_EQ(H.vector(), (Vec6<T>() << 2, 2, 2, 3, 3, 3).finished());
  EXPECT_EQ((H + H).vector(), (T(2) * H).vector());
  EXPECT_EQ((H * T(4) / T(2)).vector(), (H + H).vector());
  sva::ImpedanceVec<T> acc = H;
  acc += H;
  acc *= T(3);
  acc /= T(6);
  EXPECT_EQ(acc, H);
  EXPECT_NE(acc, sva::ImpedanceVec<T>::Zero());
  EXPECT_EQ(sva::AdmittanceVec<T>(T(1), T(2)).template cast<double>().vector(),
            (Eigen::Vector6d() << 1, 1, 1, 2, 2, 2).finished());
}

/// The right Jacobian of SO(3), Jr(u) = 1 - (1 - cos t)/t² u^ + (t - sin t)/t³ u^², t = |u|,
/// written in long double (its own series below t = 0.1).
inline Eigen::Matrix<long double, 3, 3> rightJacobian(const Eigen::Matrix<long double, 3, 1> & u)
{
  const long double t = u.norm(), t2 = t * t;
  const long double t4 = t2 * t2;
  const long double a = t < 0.1L ? 0.5L - t2 / 24 + t4 / 720 - t4 * t2 / 40320 + t4 * t4 / 3628800 : (1 - std::cos(t)) / t2;
  const long double b =
      t < 0.1L ? 1.0L / 6 - t2 / 120 + t4 / 5040 - t4 * t2 / 362880 + t4 * t4 / 39916800 : (t - std::sin(t)) / (t2 * t);
  const Mat3<long double> ux = skew<long double>(u);
  return Mat3<long double>::Identity() - a * ux + b * ux * ux;
}

// SO3RightJacInv(u) Jr(u) = 1 for |u| from 0 to 3 (both sides of the series/closed-form switch at
// 3), and SO3RightJacInvDot is the derivative of SO3RightJacInv along u + t du.
TYPED_TEST(SvaApi, SO3RightJacobianInverse)
{
  using T = TypeParam;
  using LD = long double;
  Rand<T> rnd(14);
  EXPECT_EQ(sva::SO3RightJacInv<T>(Vec3<T>::Zero()), Mat3<T>::Identity());
  for(T norm : {T(1e-9), T(1e-4), T(0.3), T(0.999), T(1.0), T(1.5), T(2.5), T(2.999), T(3.001), T(3.0), T(5.0)})
  {
    const Vec3<T> u = rnd.unit3() * norm, du = rnd.vec3();
    const Mat3<T> Jinv = sva::SO3RightJacInv(u);
    const Mat3<LD> prod = Jinv.template cast<LD>() * rightJacobian(u.template cast<LD>());
    EXPECT_TRUE(near(prod, Mat3<LD>::Identity(), LD(100) * LD(std::numeric_limits<T>::epsilon()))) << norm;
    // derivative against a central difference of the long double function (step 1e-6)
    const LD hd = 1e-6L;
    const Vec3<LD> uL = u.template cast<LD>(), duL = du.template cast<LD>();
    const Mat3<LD> diff = (sva::SO3RightJacInv<LD>(Vec3<LD>(uL + hd * duL)) - sva::SO3RightJacInv<LD>(Vec3<LD>(uL - hd * duL))) / (2 * hd);
    EXPECT_TRUE(near(sva::SO3RightJacInvDot(u, du).template cast<LD>(), diff,
                     std::max(LD(1e-9), LD(100) * LD(std::numeric_limits<T>::epsilon()))))
        << norm;
  }
}
