// MotionVec / ForceVec: construction, arithmetic, cross products and dot product, against the
// explicit 6-vectors and crm / crf matrices of Featherstone's appendix A.
#include <sstream>

#include <gtest/gtest.h>

#include <sva/SpaceVecAlg.h>

#include "SvaTestUtils.h"

using namespace svatest;

template<class T>
class SvaVectors : public ::testing::Test
{
};
TYPED_TEST_SUITE(SvaVectors, Scalars, );

TYPED_TEST(SvaVectors, MotionVecConstructionAndAccessors)
{
  using T = TypeParam;
  Rand<T> rnd(1);
  const Vec3<T> w = rnd.vec3(), v = rnd.vec3();
  Vec6<T> wv;
  wv << w, v;

  const sva::MotionVec<T> a(w, v);
  EXPECT_EQ(a.angular(), w);
  EXPECT_EQ(a.linear(), v);
  EXPECT_EQ(a.vector(), wv);

  const sva::MotionVec<T> b(wv);
  EXPECT_EQ(b.angular(), w);
  EXPECT_EQ(b.linear(), v);
  EXPECT_TRUE(a == b);
  EXPECT_FALSE(a != b);

  EXPECT_EQ(sva::MotionVec<T>::Zero().vector(), Vec6<T>::Zero());

  sva::MotionVec<T> c = a;
  c.angular() = v;
  c.linear() = w;
  EXPECT_EQ(c.angular(), v);
  EXPECT_EQ(c.linear(), w);
  EXPECT_TRUE(c != a);
  c.angular().x() += T(1);
  EXPECT_EQ(c.angular().x(), v.x() + T(1));
}

TYPED_TEST(SvaVectors, ForceVecConstructionAndAccessors)
{
  using T = TypeParam;
  Rand<T> rnd(2);
  const Vec3<T> n = rnd.vec3(), f = rnd.vec3();
  Vec6<T> nf;
  nf << n, f;

  const sva::ForceVec<T> a(n, f);
  EXPECT_EQ(a.couple(), n);
  EXPECT_EQ(a.force(), f);
  EXPECT_EQ(a.vector(), nf);

  const sva::ForceVec<T> b(nf);
  EXPECT_EQ(b.couple(), n);
  EXPECT_EQ(b.force(), f);
  EXPECT_TRUE(a == b);
  EXPECT_FALSE(a != b);

  EXPECT_EQ(sva::ForceVec<T>::Zero().vector(), Vec6<T>::Zero());

  sva::ForceVec<T> c = a;
  c.couple() = f;
  c.force() = n;
  EXPECT_EQ(c.couple(), f);
  EXPECT_EQ(c.force(), n);
  EXPECT_TRUE(c != a);
}

TYPED_TEST(SvaVectors, MotionVecArithmetic)
{
  using T = TypeParam;
  Rand<T> rnd(3);
  for(int k = 0; k < 20; ++k)
  {
    const Vec6<T> x = rnd.vec6(), y = rnd.vec6();
    const T s = rnd.uniform(T(0.5), T(3));
    const sva::MotionVec<T> a(x), b(y);

    EXPECT_TRUE(near((a + b).vector(), Vec6<T>(x + y)));
    EXPECT_TRUE(near((a - b).vector(), Vec6<T>(x - y)));
    EXPECT_TRUE(near((-a).vector(), Vec6<T>(-x)));
    EXPECT_TRUE(near((a * s).vector(), Vec6<T>(x * s)));
    EXPECT_TRUE(near((s * a).vector(), Vec6<T>(x * s)));
    EXPECT_TRUE(near((a / s).vector(), Vec6<T>(x / s)));

    sva::MotionVec<T> c = a;
    c += b;
    EXPECT_TRUE(near(c.vector(), Vec6<T>(x + y)));
    c -= b;
    c -= b;
    EXPECT_TRUE(near(c.vector(), Vec6<T>(x - y)));
    c = a;
    c *= s;
    EXPECT_TRUE(near(c.vector(), Vec6<T>(x * s)));
    c /= s;
    EXPECT_TRUE(near(c.vector(), x));
  }
  // Integer scalars convert.
  const sva::MotionVec<T> a(rnd.vec6());
  EXPECT_EQ((2 * a).vector(), (a * T(2)).vector());
  EXPECT_EQ((a * 2).vector(), (a * T(2)).vector());
}

TYPED_TEST(SvaVectors, ForceVecArithmetic)
{
  using T = TypeParam;
  Rand<T> rnd(4);
  for(int k = 0; k < 20; ++k)
  {
    const Vec6<T> x = rnd.vec6(), y = rnd.vec6();
    const T s = rnd.uniform(T(0.5), T(3));
    const sva::ForceVec<T> a(x), b(y);

    EXPECT_TRUE(near((a + b).vector(), Vec6<T>(x + y)));
    EXPECT_TRUE(near((a - b).vector(), Vec6<T>(x - y)));
    EXPECT_TRUE(near((-a).vector(), Vec6<T>(-x)));
    EXPECT_TRUE(near((a * s).vector(), Vec6<T>(x * s)));
    EXPECT_TRUE(near((s * a).vector(), Vec6<T>(x * s)));
    EXPECT_TRUE(near((a / s).vector(), Vec6<T>(x / s)));

    sva::ForceVec<T> c = a;
    c += b;
    EXPECT_TRUE(near(c.vector(), Vec6<T>(x + y)));
    c -= b;
    c -= b;
    EXPECT_TRUE(near(c.vector(), Vec6<T>(x - y)));
    c = a;
    c *= s;
    EXPECT_TRUE(near(c.vector(), Vec6<T>(x * s)));
    c /= s;
    EXPECT_TRUE(near(c.vector(), x));
  }
}

TYPED_TEST(SvaVectors, CrossProductIsCrm)
{
  using T = TypeParam;
  Rand<T> rnd(5);
  for(int k = 0; k < 50; ++k)
  {
    const Vec6<T> x = rnd.vec6(T(3)), y = rnd.vec6(T(3));
    const sva::MotionVec<T> a(x), b(y);
    // v1 x v2 = crm(v1) v2
    EXPECT_TRUE(near(a.cross(b).vector(), Vec6<T>(crm<T>(x) * y)));
    // Antisymmetry: v1 x v2 = -v2 x v1, v x v = 0.
    EXPECT_TRUE(near(a.cross(b).vector(), Vec6<T>(-b.cross(a).vector())));
    EXPECT_TRUE(near(a.cross(a).vector(), Vec6<T>::Zero()));
  }
}

TYPED_TEST(SvaVectors, CrossDualIsCrf)
{
  using T = TypeParam;
  Rand<T> rnd(6);
  for(int k = 0; k < 50; ++k)
  {
    const Vec6<T> x = rnd.vec6(T(3)), y = rnd.vec6(T(3)), z = rnd.vec6(T(3));
    const sva::MotionVec<T> v(x), u(z);
    const sva::ForceVec<T> f(y);
    // v x* f = crf(v) f, with crf(v) = -crm(v)^T
    EXPECT_TRUE(near(v.crossDual(f).vector(), Vec6<T>(crf<T>(x) * y)));
    EXPECT_TRUE(near(v.crossDual(f).vector(), Vec6<T>(-crm<T>(x).transpose() * y)));
    // Duality: (v x* f) . u = -f . (v x u)
    EXPECT_TRUE(nearScalar(u.dot(v.crossDual(f)), -f.dot(v.cross(u))));
  }
}

TYPED_TEST(SvaVectors, DotProduct)
{
  using T = TypeParam;
  Rand<T> rnd(7);
  for(int k = 0; k < 20; ++k)
  {
    const Vec6<T> x = rnd.vec6(), y = rnd.vec6();
    const sva::MotionVec<T> v(x);
    const sva::ForceVec<T> f(y);
    const T expected = x.dot(y);
    EXPECT_TRUE(nearScalar(v.dot(f), expected));
    EXPECT_TRUE(nearScalar(f.dot(v), expected));
  }
}

TYPED_TEST(SvaVectors, IsApproxAndCast)
{
  using T = TypeParam;
  Rand<T> rnd(8);
  const Vec6<T> x = rnd.vec6(), dx = rnd.vec6();
  const sva::MotionVec<T> a(x);
  const sva::MotionVec<T> b(Vec6<T>(x + dx * T(1e-9) * x.norm()));
  EXPECT_TRUE(a.isApprox(b, T(1e-6)));
  EXPECT_FALSE(a.isApprox(b, T(1e-12)));
  EXPECT_TRUE(a.isApprox(a));
  EXPECT_FALSE(a.isApprox(a * T(1.1)));

  const sva::ForceVec<T> f(x), g(Vec6<T>(x + dx * T(1e-9) * x.norm()));
  EXPECT_TRUE(f.isApprox(g, T(1e-6)));
  EXPECT_FALSE(f.isApprox(g, T(1e-12)));

  const sva::MotionVec<float> af = a.template cast<float>();
  EXPECT_TRUE(near(af.vector(), Eigen::Matrix<float, 6, 1>(x.template cast<float>()), 1e-6f));
  const sva::ForceVec<float> ff = f.template cast<float>();
  EXPECT_TRUE(near(ff.vector(), Eigen::Matrix<float, 6, 1>(x.template cast<float>()), 1e-6f));
  const sva::MotionVec<T> back = a.template cast<long double>().template cast<T>();
  EXPECT_EQ(back, a);
}

TYPED_TEST(SvaVectors, StreamOutput)
{
  using T = TypeParam;
  const sva::MotionVec<T> a(Vec3<T>(T(1), T(2), T(3)), Vec3<T>(T(4), T(5), T(6)));
  const sva::ForceVec<T> f(a.vector());
  std::ostringstream sa, sf, se;
  sa << a;
  sf << f;
  se << a.vector().transpose();
  EXPECT_EQ(sa.str(), se.str());
  EXPECT_EQ(sf.str(), se.str());
}

TYPED_TEST(SvaVectors, CrossMatrices)
{
  using T = TypeParam;
  Rand<T> rnd(9);
  for(int k = 0; k < 20; ++k)
  {
    const Vec3<T> a = rnd.vec3(), b = rnd.vec3();
    EXPECT_EQ(sva::vector3ToCrossMatrix(a), skew<T>(a));
    // a^ b = a x b (Eigen's cross as the truth)
    EXPECT_TRUE(near(Vec3<T>(sva::vector3ToCrossMatrix(a) * b), Vec3<T>(a.cross(b))));
    // From an expression.
    EXPECT_TRUE(near(sva::vector3ToCrossMatrix(a + b), skew<T>(Vec3<T>(a + b))));

    const Vec6<T> v = rnd.vec6();
    EXPECT_EQ(sva::vector6ToCrossMatrix(v), crm<T>(v));
    EXPECT_EQ(sva::vector6ToCrossDualMatrix(v), crf<T>(v));
    EXPECT_EQ(sva::vector6ToCrossMatrix(sva::MotionVec<T>(v)), crm<T>(v));
    EXPECT_EQ(sva::vector6ToCrossDualMatrix(sva::MotionVec<T>(v)), crf<T>(v));
    EXPECT_EQ(sva::vector6ToCrossDualMatrix(v), Mat6<T>(-sva::vector6ToCrossMatrix(v).transpose()));
    EXPECT_EQ(sva::vector6ToCrossMatrix(v * T(2)), crm<T>(Vec6<T>(v * T(2))));
  }
}
