// PTransform against the explicit 6x6 Pluecker matrices X = rot(E) xlt(r) = [E 0; -E r^ E] and
// X* = [E -E r^; 0 E] (and Eigen's 6x6 inverse), for vectors, inertias and 6xN matrices.
#include <sstream>

#include <gtest/gtest.h>

#include <sva/SpaceVecAlg.h>

#include "SvaTestUtils.h"

using namespace svatest;

template<class T>
class SvaPTransform : public ::testing::Test
{
};
TYPED_TEST_SUITE(SvaPTransform, Scalars, );

namespace
{

template<class T>
sva::PTransform<T> randomX(Rand<T> & rnd)
{
  return sva::PTransform<T>(rnd.rotation(), rnd.vec3(T(2)));
}

template<class T>
sva::RBInertia<T> randomRBI(Rand<T> & rnd)
{
  const T m = rnd.uniform(T(0.5), T(5));
  const Vec3<T> c = rnd.vec3();
  const Mat3<T> cx = skew(c);
  return sva::RBInertia<T>(m, Vec3<T>(m * c), Mat3<T>(rnd.spd3() + m * cx * cx.transpose()));
}

template<class T>
sva::ABInertia<T> randomABI(Rand<T> & rnd)
{
  const Mat6<T> A = rnd.spd6();
  return sva::ABInertia<T>(A.template bottomRightCorner<3, 3>(), A.template topRightCorner<3, 3>(),
                           A.template topLeftCorner<3, 3>());
}

} // namespace

TYPED_TEST(SvaPTransform, Construction)
{
  using T = TypeParam;
  Rand<T> rnd(21);
  const Mat3<T> E = rnd.rotation();
  const Vec3<T> r = rnd.vec3();
  const Eigen::Quaternion<T> q = rnd.quat();
  const Mat3<T> Eq = q.toRotationMatrix();
  const Mat3<T> I3 = Mat3<T>::Identity();
  const Vec3<T> zero = Vec3<T>::Zero();

  const sva::PTransform<T> a(E, r);
  EXPECT_EQ(a.rotation(), E);
  EXPECT_EQ(a.translation(), r);
  const sva::PTransform<T> b(q, r);
  EXPECT_EQ(b.rotation(), Eq); // the quaternion's matrix is used as E, untransposed
  EXPECT_EQ(b.translation(), r);
  const sva::PTransform<T> c(E);
  EXPECT_EQ(c.rotation(), E);
  EXPECT_EQ(c.translation(), zero);
  const sva::PTransform<T> d(q);
  EXPECT_EQ(d.rotation(), Eq);
  EXPECT_EQ(d.translation(), zero);
  const sva::PTransform<T> e(r);
  EXPECT_EQ(e.rotation(), I3);
  EXPECT_EQ(e.translation(), r);
  const sva::PTransform<T> id = sva::PTransform<T>::Identity();
  EXPECT_EQ(id.rotation(), I3);
  EXPECT_EQ(id.translation(), zero);
  EXPECT_EQ(id.matrix(), Mat6<T>(Mat6<T>::Identity()));

  // From Eigen expressions (3x3 -> rotation, 3x1 -> translation).
  const sva::PTransform<T> f(E.transpose());
  EXPECT_EQ(f.rotation(), Mat3<T>(E.transpose()));
  EXPECT_EQ(f.translation(), zero);
  const sva::PTransform<T> g(r * T(2));
  EXPECT_EQ(g.rotation(), I3);
  EXPECT_EQ(g.translation(), Vec3<T>(r * T(2)));
  const sva::PTransform<T> h(Vec3<T>::UnitX());
  EXPECT_EQ(h.translation(), Vec3<T>::UnitX());
  const sva::PTransform<T> i(E * E, r + r);
  EXPECT_EQ(i.rotation(), Mat3<T>(E * E));
  EXPECT_EQ(i.translation(), Vec3<T>(r + r));

  // Mutable accessors.
  sva::PTransform<T> m = id;
  m.rotation() = E;
  m.translation() = r;
  EXPECT_EQ(m, a);
}

TYPED_TEST(SvaPTransform, MatrixAndDualMatrix)
{
  using T = TypeParam;
  Rand<T> rnd(22);
  for(int k = 0; k < 30; ++k)
  {
    const Mat3<T> E = rnd.rotation();
    const Vec3<T> r = rnd.vec3(T(2));
    const sva::PTransform<T> X(E, r);
    EXPECT_TRUE(near(X.matrix(), plxMotion<T>(E, r)));
    EXPECT_TRUE(near(X.dualMatrix(), plxForce<T>(E, r)));
    // X* = X^-T
    EXPECT_TRUE(near(X.dualMatrix(), Mat6<T>(X.matrix().inverse().transpose())));
  }
}

TYPED_TEST(SvaPTransform, ElementaryTransforms)
{
  using T = TypeParam;
  Rand<T> rnd(23);
  const Mat3<T> Z = Mat3<T>::Zero(), I3 = Mat3<T>::Identity();
  for(int k = 0; k < 10; ++k)
  {
    const T t = rnd.uniform(T(-3), T(3));
    // rotx(t) = [rx(t) 0; 0 rx(t)], rx(t) = R_x(t)^T
    const Mat3<T> rx = rodrigues<T>(Vec3<T>::UnitX(), t).transpose();
    const Mat3<T> ry = rodrigues<T>(Vec3<T>::UnitY(), t).transpose();
    const Mat3<T> rz = rodrigues<T>(Vec3<T>::UnitZ(), t).transpose();
    EXPECT_TRUE(near(sva::PTransform<T>(sva::RotX(t)).matrix(), blocks<T>(rx, Z, Z, rx)));
    EXPECT_TRUE(near(sva::PTransform<T>(sva::RotY(t)).matrix(), blocks<T>(ry, Z, Z, ry)));
    EXPECT_TRUE(near(sva::PTransform<T>(sva::RotZ(t)).matrix(), blocks<T>(rz, Z, Z, rz)));
    // xlt(r) = [1 0; -r^ 1]
    const Vec3<T> r = rnd.vec3();
    EXPECT_TRUE(near(sva::PTransform<T>(r).matrix(), blocks<T>(I3, Z, Mat3<T>(-skew(r)), I3)));
  }
}

TYPED_TEST(SvaPTransform, FrameSemantics)
{
  using T = TypeParam;
  Rand<T> rnd(24);
  for(int k = 0; k < 10; ++k)
  {
    // X_a_b = plx(E, r): a body spinning with w about A's origin (v_A = [w; 0]) moves the point
    // at B's origin (position r in A) with linear velocity w x r; in B coordinates: E (w x r).
    const Mat3<T> E = rnd.rotation();
    const Vec3<T> r = rnd.vec3(), w = rnd.vec3();
    const sva::PTransform<T> X_a_b(E, r);
    const sva::MotionVec<T> vB = X_a_b * sva::MotionVec<T>(w, Vec3<T>::Zero());
    EXPECT_TRUE(near(vB.angular(), Vec3<T>(E * w)));
    EXPECT_TRUE(near(vB.linear(), Vec3<T>(E * w.cross(r))));
    // A pure force f through A's origin has moment (-r) x f about B's origin.
    const Vec3<T> f = rnd.vec3();
    const sva::ForceVec<T> fB = X_a_b.dualMul(sva::ForceVec<T>(Vec3<T>::Zero(), f));
    EXPECT_TRUE(near(fB.couple(), Vec3<T>(E * (-r).cross(f))));
    EXPECT_TRUE(near(fB.force(), Vec3<T>(E * f)));
  }
}

TYPED_TEST(SvaPTransform, CompositionAndInverse)
{
  using T = TypeParam;
  Rand<T> rnd(25);
  const Mat6<T> I6 = Mat6<T>::Identity();
  for(int k = 0; k < 30; ++k)
  {
    const sva::PTransform<T> X1 = randomX(rnd), X2 = randomX(rnd);
    const sva::PTransform<T> X12 = X1 * X2;
    EXPECT_TRUE(near(X12.matrix(), Mat6<T>(X1.matrix() * X2.matrix())));
    EXPECT_TRUE(near(X12.rotation(), Mat3<T>(X1.rotation() * X2.rotation())));
    EXPECT_TRUE(near(X12.translation(), Vec3<T>(X2.translation() + X2.rotation().transpose() * X1.translation())));

    EXPECT_TRUE(near(X1.inv().matrix(), Mat6<T>(X1.matrix().inverse())));
    EXPECT_TRUE(near((X1 * X1.inv()).matrix(), I6));
    EXPECT_TRUE(near((X1.inv() * X1).matrix(), I6));
    EXPECT_TRUE(near((X1 * X2).inv().matrix(), (X2.inv() * X1.inv()).matrix()));
    EXPECT_TRUE(near((X1 * sva::PTransform<T>::Identity()).matrix(), X1.matrix()));
  }
}

TYPED_TEST(SvaPTransform, MotionAndForceProducts)
{
  using T = TypeParam;
  Rand<T> rnd(26);
  for(int k = 0; k < 50; ++k)
  {
    const sva::PTransform<T> X = randomX(rnd);
    const Mat6<T> Xm = plxMotion<T>(X.rotation(), X.translation());
    const Mat6<T> Xf = plxForce<T>(X.rotation(), X.translation());
    const Mat6<T> Xinv = Xm.inverse();
    const Vec6<T> x = rnd.vec6(T(2)), y = rnd.vec6(T(2));
    const sva::MotionVec<T> v(x);
    const sva::ForceVec<T> f(y);

    EXPECT_TRUE(near((X * v).vector(), Vec6<T>(Xm * x)));                  // X v
    EXPECT_TRUE(near(X.invMul(v).vector(), Vec6<T>(Xinv * x)));            // X^-1 v
    EXPECT_TRUE(near(X.dualMul(f).vector(), Vec6<T>(Xf * y)));             // X* f
    EXPECT_TRUE(near(X.transMul(f).vector(), Vec6<T>(Xm.transpose() * y))); // X^T f
    EXPECT_TRUE(near(X.invMul(X * v).vector(), x));
    EXPECT_TRUE(near(X.transMul(X.dualMul(f)).vector(), y));
    EXPECT_TRUE(near(X.inv().dualMul(f).vector(), X.transMul(f).vector()));

    // Power is frame invariant: (X v) . (X* f) = v . f, (X^-1 v) . (X^T f) = v . f
    EXPECT_TRUE(nearScalar((X * v).dot(X.dualMul(f)), v.dot(f)));
    EXPECT_TRUE(nearScalar(X.invMul(v).dot(X.transMul(f)), v.dot(f)));
    // X^T is the adjoint of X: (X^T f) . v = f . (X v)
    EXPECT_TRUE(nearScalar(X.transMul(f).dot(v), f.dot(X * v)));

    // Cross products are frame covariant.
    const sva::MotionVec<T> u(rnd.vec6());
    EXPECT_TRUE(near((X * v.cross(u)).vector(), (X * v).cross(X * u).vector()));
    EXPECT_TRUE(near(X.dualMul(v.crossDual(f)).vector(), (X * v).crossDual(X.dualMul(f)).vector()));
  }
}

TYPED_TEST(SvaPTransform, RBInertiaTransforms)
{
  using T = TypeParam;
  Rand<T> rnd(27);
  for(int k = 0; k < 30; ++k)
  {
    const sva::PTransform<T> X = randomX(rnd);
    const Mat6<T> Xm = plxMotion<T>(X.rotation(), X.translation());
    const Mat6<T> Xf = plxForce<T>(X.rotation(), X.translation());
    const sva::RBInertia<T> I = randomRBI(rnd);
    const Mat6<T> Im = rbiMatrix<T>(I.mass(), I.momentum(), I.inertia());

    const sva::RBInertia<T> Id = X.dualMul(I); // X* I X^-1
    EXPECT_TRUE(near(Id.matrix(), Mat6<T>(Xf * Im * Xm.inverse())));
    EXPECT_EQ(Id.mass(), I.mass());
    const sva::RBInertia<T> It = X.transMul(I); // X^T I X
    EXPECT_TRUE(near(It.matrix(), Mat6<T>(Xm.transpose() * Im * Xm)));
    EXPECT_TRUE(near(X.transMul(X.dualMul(I)).matrix(), Im));
    EXPECT_TRUE(near(X.inv().dualMul(I).matrix(), It.matrix()));

    // Momentum transforms as a force: (X* I X^-1)(X v) = X* (I v)
    const sva::MotionVec<T> v(rnd.vec6());
    EXPECT_TRUE(near((Id * (X * v)).vector(), X.dualMul(I * v).vector()));
  }
}

TYPED_TEST(SvaPTransform, ABInertiaTransforms)
{
  using T = TypeParam;
  Rand<T> rnd(28);
  for(int k = 0; k < 30; ++k)
  {
    const sva::PTransform<T> X = randomX(rnd);
    const Mat6<T> Xm = plxMotion<T>(X.rotation(), X.translation());
    const Mat6<T> Xf = plxForce<T>(X.rotation(), X.translation());
    const sva::ABInertia<T> A = randomABI(rnd);
    const Mat6<T> Am = abiMatrix<T>(A.massMatrix(), A.gInertia(), A.inertia());

    EXPECT_TRUE(near(X.dualMul(A).matrix(), Mat6<T>(Xf * Am * Xm.inverse()))); // X* I^A X^-1
    EXPECT_TRUE(near(X.transMul(A).matrix(), Mat6<T>(Xm.transpose() * Am * Xm))); // X^T I^A X
    EXPECT_TRUE(near(X.transMul(X.dualMul(A)).matrix(), Am));

    // On a rigid-body inertia, the ABInertia transforms agree with the RBInertia ones.
    const sva::RBInertia<T> I = randomRBI(rnd);
    EXPECT_TRUE(near(X.dualMul(sva::ABInertia<T>(I)).matrix(), X.dualMul(I).matrix()));
    EXPECT_TRUE(near(X.transMul(sva::ABInertia<T>(I)).matrix(), X.transMul(I).matrix()));
  }
}

TYPED_TEST(SvaPTransform, SixByNProducts)
{
  using T = TypeParam;
  using Mat6X = Eigen::Matrix<T, 6, Eigen::Dynamic>;
  Rand<T> rnd(29);
  for(int n = 0; n <= 7; ++n)
  {
    const sva::PTransform<T> X = randomX(rnd);
    const Mat6<T> Xm = plxMotion<T>(X.rotation(), X.translation());
    const Mat6<T> Xf = plxForce<T>(X.rotation(), X.translation());
    const Mat6X M = rnd.mat6N(n);

    const Mat6X a = X.mul(M);
    const Mat6X b = X * M;
    const Mat6X c = X.invMul(M);
    const Mat6X d = X.dualMul(M);
    const Mat6X e = X.transMul(M);
    ASSERT_EQ(a.cols(), n);
    ASSERT_EQ(c.cols(), n);
    ASSERT_EQ(d.cols(), n);
    ASSERT_EQ(e.cols(), n);
    if(n == 0)
    {
      continue;
    }
    EXPECT_TRUE(near(a, Mat6X(Xm * M)));
    EXPECT_TRUE(near(b, Mat6X(Xm * M)));
    EXPECT_TRUE(near(c, Mat6X(Xm.inverse() * M)));
    EXPECT_TRUE(near(d, Mat6X(Xf * M)));
    EXPECT_TRUE(near(e, Mat6X(Xm.transpose() * M)));
    // Column by column, the same as the vector products.
    for(int j = 0; j < n; ++j)
    {
      EXPECT_TRUE(near(Vec6<T>(a.col(j)), (X * sva::MotionVec<T>(M.col(j))).vector()));
      EXPECT_TRUE(near(Vec6<T>(e.col(j)), X.transMul(sva::ForceVec<T>(M.col(j))).vector()));
    }
  }

  // Fixed sizes and expressions.
  const sva::PTransform<T> X = randomX(rnd);
  const Mat6<T> Xm = X.matrix();
  const Eigen::Matrix<T, 6, 3> M3 = rnd.mat6N(3);
  const Eigen::Matrix<T, 6, 3> a3 = X.mul(M3);
  EXPECT_TRUE(near(a3, Eigen::Matrix<T, 6, 3>(Xm * M3)));
  const Vec6<T> x = rnd.vec6();
  const Vec6<T> ax = X * x; // a 6x1 matrix is a motion vector
  EXPECT_TRUE(near(ax, (X * sva::MotionVec<T>(x)).vector()));
  const Vec6<T> col = X.invMul(M3.col(1));
  EXPECT_TRUE(near(col, X.invMul(sva::MotionVec<T>(M3.col(1))).vector()));
  const Mat6X blk = X.dualMul(M3.leftCols(2) * T(2));
  EXPECT_TRUE(near(blk, Mat6X(X.dualMatrix() * M3.leftCols(2) * T(2))));
}

TYPED_TEST(SvaPTransform, CompareCastStream)
{
  using T = TypeParam;
  Rand<T> rnd(30);
  const sva::PTransform<T> X = randomX(rnd);
  const sva::PTransform<T> Y(X.rotation(), Vec3<T>(X.translation() * (T(1) + T(1e-10))));
  EXPECT_TRUE(X == X);
  EXPECT_FALSE(X != X);
  EXPECT_TRUE(X != Y);
  EXPECT_TRUE(X.isApprox(Y, T(1e-8)));
  EXPECT_FALSE(X.isApprox(Y, T(1e-12)));
  EXPECT_TRUE((X * X.inv()).rotation().isApprox(Mat3<T>::Identity(), T(1e-12)));

  const sva::PTransform<float> Xf = X.template cast<float>();
  EXPECT_TRUE(near(Xf.matrix(), Eigen::Matrix<float, 6, 6>(X.matrix().template cast<float>()), 1e-6f));
  EXPECT_EQ(X.template cast<long double>().template cast<T>(), X);

  std::ostringstream s1, s2;
  s1 << X;
  s2 << X.matrix();
  EXPECT_EQ(s1.str(), s2.str());
}
