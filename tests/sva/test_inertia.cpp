// RBInertia / ABInertia against the explicit 6x6 matrices rbi(m, h, I) = [I h^; h^T m1],
// mcI(m, c, Ic) and abi(M, H, I) = [I H; H^T M].
#include <sstream>

#include <gtest/gtest.h>

#include <sva/SpaceVecAlg.h>

#include "SvaTestUtils.h"

using namespace svatest;

template<class T>
class SvaInertia : public ::testing::Test
{
};
TYPED_TEST_SUITE(SvaInertia, Scalars, );

namespace
{

template<class T>
sva::RBInertia<T> randomRBI(Rand<T> & rnd)
{
  const T m = rnd.uniform(T(0.5), T(5));
  const Vec3<T> c = rnd.vec3();
  const Mat3<T> Ic = rnd.spd3();
  const Mat3<T> cx = skew(c);
  return sva::RBInertia<T>(m, Vec3<T>(m * c), Mat3<T>(Ic + m * cx * cx.transpose()));
}

template<class T>
sva::ABInertia<T> randomABI(Rand<T> & rnd)
{
  const Mat6<T> A = rnd.spd6();
  return sva::ABInertia<T>(A.template bottomRightCorner<3, 3>(), A.template topRightCorner<3, 3>(),
                           A.template topLeftCorner<3, 3>());
}

/// The lower triangle of m plus garbage above the diagonal.
template<class T>
Mat3<T> lowerWithGarbage(const Mat3<T> & m)
{
  Mat3<T> g = m;
  g(0, 1) = T(123);
  g(0, 2) = T(-45);
  g(1, 2) = T(6.5);
  return g;
}

} // namespace

TYPED_TEST(SvaInertia, RBInertiaConstructionAndMatrix)
{
  using T = TypeParam;
  Rand<T> rnd(11);
  for(int k = 0; k < 20; ++k)
  {
    const T m = rnd.uniform(T(0.5), T(5));
    const Vec3<T> h = rnd.vec3();
    const Mat3<T> I = rnd.spd3();
    const sva::RBInertia<T> rbi(m, h, lowerWithGarbage(I));

    EXPECT_EQ(rbi.mass(), m);
    EXPECT_EQ(rbi.momentum(), h);
    EXPECT_EQ(rbi.inertia(), I); // symmetric matrix from the lower triangle
    const Mat3<T> lower = I.template triangularView<Eigen::Lower>();
    EXPECT_EQ(rbi.lowerTriangularInertia(), lower);
    EXPECT_EQ(rbi.matrix(), rbiMatrix<T>(m, h, I));
    EXPECT_EQ(sva::RBInertia<T>(m, h, lower), rbi);
  }
  const Mat6<T> zero = Mat6<T>::Zero();
  EXPECT_EQ(sva::RBInertia<T>().matrix(), zero);
  EXPECT_EQ(sva::RBInertia<T>::Zero().matrix(), zero);
}

TYPED_TEST(SvaInertia, RBInertiaFromCenterOfMassIsMcI)
{
  using T = TypeParam;
  Rand<T> rnd(12);
  for(int k = 0; k < 20; ++k)
  {
    const T m = rnd.uniform(T(0.5), T(5));
    const Vec3<T> c = rnd.vec3();
    const Mat3<T> Ic = rnd.spd3();
    const sva::RBInertia<T> rbi(m, Vec3<T>(m * c), sva::inertiaToOrigin(Ic, m, c, Mat3<T>::Identity()));
    EXPECT_TRUE(near(rbi.matrix(), mcI<T>(m, c, Ic)));
  }
}

TYPED_TEST(SvaInertia, RBInertiaTimesMotion)
{
  using T = TypeParam;
  Rand<T> rnd(13);
  for(int k = 0; k < 50; ++k)
  {
    const sva::RBInertia<T> rbi = randomRBI(rnd);
    const Vec6<T> v = rnd.vec6(T(2));
    const sva::ForceVec<T> f = rbi * sva::MotionVec<T>(v);
    EXPECT_TRUE(near(f.vector(), Vec6<T>(rbi.matrix() * v)));
    // Kinetic energy is positive.
    EXPECT_GT(sva::MotionVec<T>(v).dot(f), T(0));
  }
}

TYPED_TEST(SvaInertia, RBInertiaArithmetic)
{
  using T = TypeParam;
  Rand<T> rnd(14);
  for(int k = 0; k < 20; ++k)
  {
    const sva::RBInertia<T> a = randomRBI(rnd), b = randomRBI(rnd);
    const Mat6<T> A = a.matrix(), B = b.matrix();
    const T s = rnd.uniform(T(0.5), T(3));
    EXPECT_TRUE(near((a + b).matrix(), Mat6<T>(A + B)));
    EXPECT_TRUE(near((a - b).matrix(), Mat6<T>(A - B)));
    EXPECT_TRUE(near((-a).matrix(), Mat6<T>(-A)));
    EXPECT_TRUE(near((a * s).matrix(), Mat6<T>(A * s)));
    EXPECT_TRUE(near((s * a).matrix(), Mat6<T>(A * s)));
    sva::RBInertia<T> c = a;
    c += b;
    EXPECT_TRUE(near(c.matrix(), Mat6<T>(A + B)));
    c -= b;
    c -= b;
    EXPECT_TRUE(near(c.matrix(), Mat6<T>(A - B)));
  }
}

TYPED_TEST(SvaInertia, RBInertiaCompareAndCast)
{
  using T = TypeParam;
  Rand<T> rnd(15);
  const sva::RBInertia<T> a = randomRBI(rnd);
  const sva::RBInertia<T> b(a.mass() * (T(1) + T(1e-10)), a.momentum(), a.inertia());
  EXPECT_TRUE(a == a);
  EXPECT_FALSE(a != a);
  EXPECT_TRUE(a != b);
  EXPECT_TRUE(a.isApprox(b, T(1e-8)));
  EXPECT_FALSE(a.isApprox(b, T(1e-12)));
  EXPECT_FALSE(a.isApprox(a * T(1.01)));

  const sva::RBInertia<float> af = a.template cast<float>();
  EXPECT_TRUE(near(af.matrix(), Eigen::Matrix<float, 6, 6>(a.matrix().template cast<float>()), 1e-6f));
  EXPECT_EQ(a.template cast<long double>().template cast<T>(), a);

  std::ostringstream s1, s2;
  s1 << a;
  s2 << a.matrix();
  EXPECT_EQ(s1.str(), s2.str());
}

TYPED_TEST(SvaInertia, ABInertiaConstructionAndMatrix)
{
  using T = TypeParam;
  Rand<T> rnd(16);
  for(int k = 0; k < 20; ++k)
  {
    const Mat6<T> A = rnd.spd6();
    const Mat3<T> I = A.template topLeftCorner<3, 3>(), H = A.template topRightCorner<3, 3>(),
                  M = A.template bottomRightCorner<3, 3>();
    const sva::ABInertia<T> abi(lowerWithGarbage(M), H, lowerWithGarbage(I));
    EXPECT_EQ(abi.massMatrix(), M);
    EXPECT_EQ(abi.gInertia(), H);
    EXPECT_EQ(abi.inertia(), I);
    EXPECT_EQ(abi.lowerTriangularMassMatrix(), Mat3<T>(M.template triangularView<Eigen::Lower>()));
    EXPECT_EQ(abi.lowerTriangularInertia(), Mat3<T>(I.template triangularView<Eigen::Lower>()));
    EXPECT_EQ(abi.matrix(), abiMatrix<T>(M, H, I));
    EXPECT_EQ(abi.matrix(), A);
  }
  const Mat6<T> zero = Mat6<T>::Zero();
  EXPECT_EQ(sva::ABInertia<T>().matrix(), zero);
  EXPECT_EQ(sva::ABInertia<T>::Zero().matrix(), zero);
}

TYPED_TEST(SvaInertia, ABInertiaTimesMotion)
{
  using T = TypeParam;
  Rand<T> rnd(17);
  for(int k = 0; k < 50; ++k)
  {
    const sva::ABInertia<T> abi = randomABI(rnd);
    const Vec6<T> v = rnd.vec6(T(2));
    EXPECT_TRUE(near((abi * sva::MotionVec<T>(v)).vector(), Vec6<T>(abi.matrix() * v)));
  }
}

TYPED_TEST(SvaInertia, ABInertiaFromRBInertia)
{
  using T = TypeParam;
  Rand<T> rnd(18);
  for(int k = 0; k < 20; ++k)
  {
    const sva::RBInertia<T> rbi = randomRBI(rnd);
    // abi(m1, h^, I) has the same matrix as rbi(m, h, I)
    EXPECT_TRUE(near(sva::ABInertia<T>(rbi).matrix(), rbi.matrix()));
    EXPECT_TRUE(near(sva::toABInertia(rbi).matrix(), rbiMatrix<T>(rbi.mass(), rbi.momentum(), rbi.inertia())));
    const Vec6<T> v = rnd.vec6();
    EXPECT_TRUE(near((sva::toABInertia(rbi) * sva::MotionVec<T>(v)).vector(), (rbi * sva::MotionVec<T>(v)).vector()));
  }
}

TYPED_TEST(SvaInertia, ABInertiaArithmetic)
{
  using T = TypeParam;
  Rand<T> rnd(19);
  for(int k = 0; k < 20; ++k)
  {
    const sva::ABInertia<T> a = randomABI(rnd), b = randomABI(rnd);
    const sva::RBInertia<T> r = randomRBI(rnd);
    const Mat6<T> A = a.matrix(), B = b.matrix(), R = rbiMatrix<T>(r.mass(), r.momentum(), r.inertia());
    const T s = rnd.uniform(T(0.5), T(3));

    EXPECT_TRUE(near((a + b).matrix(), Mat6<T>(A + B)));
    EXPECT_TRUE(near((a + r).matrix(), Mat6<T>(A + R)));
    EXPECT_TRUE(near((r + a).matrix(), Mat6<T>(A + R)));
    EXPECT_TRUE(near((a - b).matrix(), Mat6<T>(A - B)));
    EXPECT_TRUE(near((a - r).matrix(), Mat6<T>(A - R)));
    EXPECT_TRUE(near((r - a).matrix(), Mat6<T>(R - A)));
    EXPECT_TRUE(near((-a).matrix(), Mat6<T>(-A)));
    EXPECT_TRUE(near((a * s).matrix(), Mat6<T>(A * s)));
    EXPECT_TRUE(near((s * a).matrix(), Mat6<T>(A * s)));

    sva::ABInertia<T> c = a;
    c += b;
    EXPECT_TRUE(near(c.matrix(), Mat6<T>(A + B)));
    c += r;
    EXPECT_TRUE(near(c.matrix(), Mat6<T>(A + B + R)));
    c -= b;
    EXPECT_TRUE(near(c.matrix(), Mat6<T>(A + R)));
    c -= r;
    c -= r;
    EXPECT_TRUE(near(c.matrix(), Mat6<T>(A - R)));
  }
}

TYPED_TEST(SvaInertia, ABInertiaCompareAndCast)
{
  using T = TypeParam;
  Rand<T> rnd(20);
  const sva::ABInertia<T> a = randomABI(rnd);
  const sva::ABInertia<T> b(a.massMatrix(), a.gInertia() * (T(1) + T(1e-10)), a.inertia());
  EXPECT_TRUE(a == a);
  EXPECT_FALSE(a != a);
  EXPECT_TRUE(a != b);
  EXPECT_TRUE(a.isApprox(b, T(1e-8)));
  EXPECT_FALSE(a.isApprox(b, T(1e-12)));

  const sva::ABInertia<float> af = a.template cast<float>();
  EXPECT_TRUE(near(af.matrix(), Eigen::Matrix<float, 6, 6>(a.matrix().template cast<float>()), 1e-6f));
  EXPECT_EQ(a.template cast<long double>().template cast<T>(), a);

  std::ostringstream s1, s2;
  s1 << a;
  s2 << a.matrix();
  EXPECT_EQ(s1.str(), s2.str());
}
