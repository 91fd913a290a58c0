// Free functions: RotX/Y/Z, rotation log map (near 0 and pi too), rotation/transform errors,
// parallel-axis theorem, sinc, interpolation, and the homogeneous/affine conversions.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include <sva/SpaceVecAlg.h>

#include "SvaTestUtils.h"

using namespace svatest;

template<class T>
class SvaUtility : public ::testing::Test
{
};
TYPED_TEST_SUITE(SvaUtility, Scalars, );

namespace
{

template<class T>
T pi()
{
  return T(3.141592653589793238462643383279502884L);
}

/// sva rotation for the usual rotation about unit axis a by t: E = R(a, t)^T (Eigen as the truth).
template<class T>
Mat3<T> svaRot(const Vec3<T> & a, T t)
{
  return Eigen::AngleAxis<T>(t, a).toRotationMatrix().transpose();
}

} // namespace

TYPED_TEST(SvaUtility, ElementaryRotationsAreTransposedRotations)
{
  using T = TypeParam;
  Rand<T> rnd(31);
  for(int k = 0; k < 20; ++k)
  {
    const T t = rnd.uniform(T(-4), T(4));
    EXPECT_TRUE(near(sva::RotX(t), svaRot<T>(Vec3<T>::UnitX(), t)));
    EXPECT_TRUE(near(sva::RotY(t), svaRot<T>(Vec3<T>::UnitY(), t)));
    EXPECT_TRUE(near(sva::RotZ(t), svaRot<T>(Vec3<T>::UnitZ(), t)));
    const T c = std::cos(t), s = std::sin(t);
    Mat3<T> rz;
    rz << c, s, T(0), -s, c, T(0), T(0), T(0), T(1);
    EXPECT_TRUE(near(sva::RotZ(t), rz));
  }
}

TYPED_TEST(SvaUtility, RotationVelocityRandom)
{
  using T = TypeParam;
  Rand<T> rnd(32);
  for(int k = 0; k < 500; ++k)
  {
    const Vec3<T> a = rnd.unit3();
    const T t = rnd.uniform(T(0), pi<T>());
    const Vec3<T> w = sva::rotationVelocity(svaRot<T>(a, t));
    EXPECT_TRUE(near(w, Vec3<T>(t * a))) << "angle " << static_cast<double>(t);
    // Expression argument (E^T is the usual rotation, whose log is -w).
    EXPECT_TRUE(near(sva::rotationVelocity(svaRot<T>(a, t).transpose()), Vec3<T>(-t * a)));
  }
  // Random rotation matrices: exp(w^)^T = E.
  for(int k = 0; k < 200; ++k)
  {
    const Mat3<T> E = rnd.rotation();
    const Vec3<T> w = sva::rotationVelocity(E);
    ASSERT_LE(w.norm(), pi<T>() * (T(1) + tol<T>()));
    EXPECT_TRUE(near(svaRot<T>(Vec3<T>(w.normalized()), w.norm()), E));
  }
}

TYPED_TEST(SvaUtility, RotationVelocityNearZero)
{
  using T = TypeParam;
  Rand<T> rnd(33);
  EXPECT_EQ(sva::rotationVelocity(Mat3<T>(Mat3<T>::Identity())), Vec3<T>(Vec3<T>::Zero()));
  for(const T t : {T(1e-12), T(1e-9), T(1e-6), T(1e-3), T(1e-15)})
  {
    for(int k = 0; k < 20; ++k)
    {
      const Vec3<T> a = rnd.unit3();
      const Vec3<T> w = sva::rotationVelocity(svaRot<T>(a, t));
      // Relative accuracy on the (tiny) vector.
      EXPECT_LE((w - t * a).norm(), T(100) * std::numeric_limits<T>::epsilon() * t)
          << "angle " << static_cast<double>(t);
    }
  }
}

TYPED_TEST(SvaUtility, RotationVelocityNearPi)
{
  using T = TypeParam;
  Rand<T> rnd(34);
  for(const T d : {T(1e-9), T(1e-12), T(1e-6), T(1e-3), T(0.5)})
  {
    for(int k = 0; k < 20; ++k)
    {
      const Vec3<T> a = rnd.unit3();
      const T t = pi<T>() - d;
      const Vec3<T> w = sva::rotationVelocity(svaRot<T>(a, t));
      EXPECT_TRUE(near(w, Vec3<T>(t * a))) << "pi - " << static_cast<double>(d);
    }
  }
  // Exactly pi: either of +-pi a.
  for(int k = 0; k < 20; ++k)
  {
    const Vec3<T> a = rnd.unit3();
    const Vec3<T> w = sva::rotationVelocity(svaRot<T>(a, pi<T>()));
    EXPECT_TRUE(near(w, Vec3<T>(pi<T>() * a)) || near(w, Vec3<T>(-pi<T>() * a)));
  }
  for(int i = 0; i < 3; ++i)
  {
    Mat3<T> E = -Mat3<T>::Identity();
    E(i, i) = T(1); // half turn about axis i
    const Vec3<T> w = sva::rotationVelocity(E);
    EXPECT_TRUE(nearScalar(w.norm(), pi<T>()));
    EXPECT_TRUE(nearScalar(std::abs(w(i)), pi<T>()));
  }
}

TYPED_TEST(SvaUtility, RotationError)
{
  using T = TypeParam;
  Rand<T> rnd(35);
  for(int k = 0; k < 100; ++k)
  {
    // R_ac = exp(w^) R_ab: c is b rotated by w (world/a frame); the error is w.
    const Mat3<T> R_ab = rnd.rotation();
    const Vec3<T> a = rnd.unit3();
    const T t = rnd.uniform(T(0), T(3));
    const Vec3<T> w = t * a;
    const Mat3<T> R_ac = Eigen::AngleAxis<T>(t, a).toRotationMatrix() * R_ab;
    const Mat3<T> E_a_b = R_ab.transpose(), E_a_c = R_ac.transpose();
    EXPECT_TRUE(near(sva::rotationError(E_a_b, E_a_c), w));
    EXPECT_TRUE(near(sva::rotationError(R_ab.transpose(), R_ac.transpose()), w)); // expressions
    EXPECT_TRUE(near(sva::rotationError(E_a_b, E_a_b), Vec3<T>(Vec3<T>::Zero())));

    const Vec3<T> r_b = rnd.vec3(), r_c = rnd.vec3();
    const sva::MotionVec<T> err = sva::transformError(sva::PTransform<T>(E_a_b, r_b), sva::PTransform<T>(E_a_c, r_c));
    EXPECT_TRUE(near(err.angular(), w));
    EXPECT_TRUE(near(err.linear(), Vec3<T>(r_c - r_b)));
  }
}

TYPED_TEST(SvaUtility, TransformVelocity)
{
  using T = TypeParam;
  Rand<T> rnd(36);
  for(int k = 0; k < 50; ++k)
  {
    const Vec3<T> a = rnd.unit3(), r = rnd.vec3();
    const T t = rnd.uniform(T(0), pi<T>());
    const sva::MotionVec<T> v = sva::transformVelocity(sva::PTransform<T>(svaRot<T>(a, t), r));
    EXPECT_TRUE(near(v.angular(), Vec3<T>(t * a)));
    EXPECT_EQ(v.linear(), r);
  }
  EXPECT_EQ(sva::transformVelocity(sva::PTransform<T>::Identity()).vector(), Vec6<T>(Vec6<T>::Zero()));
}

TYPED_TEST(SvaUtility, InertiaToOriginParallelAxis)
{
  using T = TypeParam;
  Rand<T> rnd(37);
  for(int k = 0; k < 20; ++k)
  {
    // A cloud of point masses: q_i in a CoM frame C (rotated by R from the body frame),
    // p_i = c + R q_i in body coordinates.
    const int n = 7;
    std::vector<T> m(n);
    std::vector<Vec3<T>> q(n);
    T mass = T(0);
    Vec3<T> qc = Vec3<T>::Zero();
    for(int i = 0; i < n; ++i)
    {
      m[i] = rnd.uniform(T(0.1), T(2));
      q[i] = rnd.vec3();
      mass += m[i];
      qc += m[i] * q[i];
    }
    qc /= mass;
    const Mat3<T> R = rnd.rotation();
    const Vec3<T> c = rnd.vec3(T(2));
    Mat3<T> Ic = Mat3<T>::Zero(), IO = Mat3<T>::Zero();
    Vec3<T> h = Vec3<T>::Zero();
    for(int i = 0; i < n; ++i)
    {
      const Vec3<T> qi = q[i] - qc; // about the CoM
      Ic += m[i] * (qi.squaredNorm() * Mat3<T>::Identity() - qi * qi.transpose());
      const Vec3<T> p = c + R * qi;
      IO += m[i] * (p.squaredNorm() * Mat3<T>::Identity() - p * p.transpose());
      h += m[i] * p;
    }
    EXPECT_TRUE(near(sva::inertiaToOrigin(Ic, mass, c, R), IO));
    EXPECT_TRUE(near(h, Vec3<T>(mass * c)));
    // Parallel-axis formula: R Ic R^T + m (|c|^2 1 - c c^T)
    const Mat3<T> pa = R * Ic * R.transpose() + mass * (c.squaredNorm() * Mat3<T>::Identity() - c * c.transpose());
    EXPECT_TRUE(near(sva::inertiaToOrigin(Ic, mass, c, R), pa));
    // Expression arguments.
    EXPECT_TRUE(near(sva::inertiaToOrigin(Ic, mass, Vec3<T>(h / mass), R.transpose().transpose()), IO));
  }
}

TYPED_TEST(SvaUtility, Sinc)
{
  using T = TypeParam;
  EXPECT_EQ(sva::sinc(T(0)), T(1));
  EXPECT_EQ(sva::sinc_inv(T(0)), T(1));
  for(const T x : {T(1e-12), T(1e-6), T(1e-4), T(1e-3), T(0.1), T(0.7), T(1.5), T(-2.5), T(3)})
  {
    EXPECT_TRUE(nearScalar(sva::sinc(x), T(std::sin(x) / x), T(10) * std::numeric_limits<T>::epsilon()));
    EXPECT_TRUE(nearScalar(sva::sinc_inv(x), T(x / std::sin(x)), T(10) * std::numeric_limits<T>::epsilon()));
  }
}

TYPED_TEST(SvaUtility, Interpolate)
{
  using T = TypeParam;
  Rand<T> rnd(38);
  for(int k = 0; k < 30; ++k)
  {
    const sva::PTransform<T> X1(rnd.rotation(), rnd.vec3()), X2(rnd.rotation(), rnd.vec3());
    EXPECT_TRUE(near(sva::interpolate(X1, X2, T(0)).matrix(), X1.matrix()));
    EXPECT_TRUE(near(sva::interpolate(X1, X2, T(1)).matrix(), X2.matrix()));
    const T tau = rnd.uniform(T(0), T(1));
    const sva::PTransform<T> Xt = sva::interpolate(X1, X2, tau);
    // R(tau) = R1 exp(tau log(R1^T R2)) with R = E^T (shortest path).
    const Mat3<T> R1 = X1.rotation().transpose(), R2 = X2.rotation().transpose();
    const Eigen::AngleAxis<T> rel(Mat3<T>(R1.transpose() * R2));
    const Mat3<T> Rt = R1 * Eigen::AngleAxis<T>(tau * rel.angle(), rel.axis()).toRotationMatrix();
    EXPECT_TRUE(near(Xt.rotation(), Mat3<T>(Rt.transpose())));
    EXPECT_TRUE(near(Xt.translation(), Vec3<T>((T(1) - tau) * X1.translation() + tau * X2.translation())));
  }
}

TYPED_TEST(SvaUtility, HomogeneousConversions)
{
  using T = TypeParam;
  using Mat4 = Eigen::Matrix<T, 4, 4>;
  namespace conv = sva::conversions;
  Rand<T> rnd(39);
  for(int k = 0; k < 20; ++k)
  {
    const Mat3<T> E = rnd.rotation();
    const Vec3<T> r = rnd.vec3();
    const sva::PTransform<T> X(E, r);

    const Mat4 H = conv::toHomogeneous(X);
    EXPECT_EQ(Mat3<T>(H.template topLeftCorner<3, 3>()), Mat3<T>(E.transpose()));
    EXPECT_EQ(Vec3<T>(H.template topRightCorner<3, 1>()), r);
    const Eigen::Matrix<T, 1, 4> lastRow(T(0), T(0), T(0), T(1));
    EXPECT_EQ(H.row(3), lastRow);
    EXPECT_EQ(conv::toHomogeneous(X, conv::RightHanded), H);
    // A point with coordinates p_B in B has coordinates p_A = E^T p_B + r in A.
    const Vec3<T> pB = rnd.vec3();
    const Eigen::Matrix<T, 4, 1> pA = H * Eigen::Matrix<T, 4, 1>(pB(0), pB(1), pB(2), T(1));
    EXPECT_TRUE(near(Vec3<T>(pA.template head<3>()), Vec3<T>(E.transpose() * pB + r)));
    EXPECT_TRUE(near(Vec3<T>(E * (Vec3<T>(pA.template head<3>()) - r)), pB));

    const Mat4 L = conv::toHomogeneous(X, conv::LeftHanded);
    EXPECT_EQ(Mat3<T>(L.template topLeftCorner<3, 3>()), E);
    EXPECT_EQ(Vec3<T>(L.template topRightCorner<3, 1>()), r);

    EXPECT_EQ(conv::fromHomogeneous(H), X);
    EXPECT_EQ(conv::fromHomogeneous(L, conv::LeftHanded), X);

    // X1 * X2 applies X2 first: homogeneous matrices compose the other way round.
    const sva::PTransform<T> Y(rnd.rotation(), rnd.vec3());
    EXPECT_TRUE(near(conv::toHomogeneous(X * Y), Mat4(conv::toHomogeneous(Y) * conv::toHomogeneous(X))));

    const Eigen::Transform<T, 3, Eigen::Affine> A = conv::toAffine(X);
    EXPECT_EQ(A.matrix(), H);
    EXPECT_EQ(conv::toAffine(X, conv::LeftHanded).matrix(), L);
    EXPECT_EQ(conv::fromAffine(A), X);
    EXPECT_EQ(conv::fromAffine(conv::toAffine(X, conv::LeftHanded), conv::LeftHanded), X);
    Eigen::Transform<T, 3, Eigen::Isometry> iso = Eigen::Transform<T, 3, Eigen::Isometry>::Identity();
    iso.linear() = E.transpose();
    iso.translation() = r;
    EXPECT_EQ(conv::fromAffine(iso), X);
  }
}
