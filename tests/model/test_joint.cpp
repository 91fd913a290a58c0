// Joint: pose and motion subspace of every type and direction against closed forms, the inverse
// of the forward pose, and finite differences of the pose along the documented q(t) paths.
// Typed on double and long double.
#include <cmath>

#include <gtest/gtest.h>

#include <rbd/Joint.h>

#include "TestModels.h"

namespace
{

template<typename T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
template<typename T>
using Mat3 = Eigen::Matrix<T, 3, 3>;
template<typename T>
using Mat6 = Eigen::Matrix<T, 6, 6>;

/// Usual right-handed rotation about unit a by t (Rodrigues), written out.
template<typename T>
Mat3<T> rodrigues(const Vec3<T> & a, T t)
{
  Mat3<T> K;
  K << T(0), -a.z(), a.y(), a.z(), T(0), -a.x(), -a.y(), a.x(), T(0);
  return Mat3<T>::Identity() + std::sin(t) * K + (T(1) - std::cos(t)) * K * K;
}

/// Usual rotation of the unit quaternion (w, x, y, z), written out.
template<typename T>
Mat3<T> quatRotation(T w, T x, T y, T z)
{
  Mat3<T> R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 2 * (x * y + w * z), 1 - 2 * (x * x + z * z),
      2 * (y * z - w * x), 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

/// 6x6 cross matrix crm([w; v]) = [w^ 0; v^ w^], written out.
template<typename T>
Mat6<T> crm(const Eigen::Matrix<T, 6, 1> & m)
{
  auto hat = [](const Vec3<T> & a) {
    Mat3<T> K;
    K << T(0), -a.z(), a.y(), a.z(), T(0), -a.x(), -a.y(), a.x(), T(0);
    return K;
  };
  Mat6<T> X = Mat6<T>::Zero();
  X.template topLeftCorner<3, 3>() = hat(m.template head<3>());
  X.template bottomRightCorner<3, 3>() = hat(m.template head<3>());
  X.template bottomLeftCorner<3, 3>() = hat(m.template tail<3>());
  return X;
}

template<typename T>
double tol()
{
  return std::is_same<T, double>::value ? 1e-13 : 1e-16;
}

template<typename T>
std::vector<T> randomParam(rbdtest::Rng & rng, const rbd::JointTpl<T> & j)
{
  std::vector<T> q(static_cast<std::size_t>(j.params()));
  for(auto & x : q) x = T(rbdtest::uniform(rng, -2.5, 2.5));
  if(j.type() == rbd::Joint::Spherical || j.type() == rbd::Joint::Free)
  {
    Eigen::Matrix<T, 4, 1> quat = Eigen::Matrix<T, 4, 1>(q[0], q[1], q[2], q[3]).normalized();
    for(int k = 0; k < 4; ++k) q[static_cast<std::size_t>(k)] = quat(k);
  }
  return q;
}

/// q(t) for a constant alpha, as docs/DESIGN.md integrates it (to first order in t): Rev/Prism/Cyl
/// q + alpha t; Planar ((x, y) in successor axes) theta + thetaDot t, [x + (v_u + thetaDot y) t,
/// y + (v_w - thetaDot x) t]; Spherical/Free quat (x) exp(w t), translation + R(quat) v t.
template<typename T>
std::vector<T> path(const rbd::JointTpl<T> & j, const std::vector<T> & q, const std::vector<T> & a, T t)
{
  std::vector<T> out = q;
  switch(j.type())
  {
    case rbd::Joint::Planar:
    {
      out[0] += a[0] * t;
      out[1] += (a[1] + a[0] * q[2]) * t;
      out[2] += (a[2] - a[0] * q[1]) * t;
      return out;
    }
    case rbd::Joint::Spherical:
    case rbd::Joint::Free:
    {
      const Vec3<T> w(a[0], a[1], a[2]);
      const T n = w.norm();
      const Eigen::Quaternion<T> dq(std::cos(n * t / 2), std::sin(n * t / 2) * w.x() / n, std::sin(n * t / 2) * w.y() / n,
                                    std::sin(n * t / 2) * w.z() / n);
      const Eigen::Quaternion<T> q1 = Eigen::Quaternion<T>(q[0], q[1], q[2], q[3]) * dq;
      out[0] = q1.w();
      out[1] = q1.x();
      out[2] = q1.y();
      out[3] = q1.z();
      if(j.type() == rbd::Joint::Free)
      {
        const Vec3<T> dr = quatRotation(q[0], q[1], q[2], q[3]) * Vec3<T>(a[3], a[4], a[5]) * t;
        for(int k = 0; k < 3; ++k) out[static_cast<std::size_t>(4 + k)] += dr(k);
      }
      return out;
    }
    default:
      for(std::size_t k = 0; k < out.size(); ++k) out[k] += a[k] * t;
      return out;
  }
}

} // namespace

template<typename T>
class JointTest : public ::testing::Test
{
};
using Scalars = ::testing::Types<double, long double>;
TYPED_TEST_SUITE(JointTest, Scalars, );

TYPED_TEST(JointTest, SizesAndZeroParamIsIdentity)
{
  using T = TypeParam;
  using J = rbd::JointTpl<T>;
  const std::vector<std::tuple<typename J::Type, int, int>> sizes{{J::Rev, 1, 1},   {J::Prism, 1, 1},       {J::Cylindrical, 2, 2},
                                                                  {J::Planar, 3, 3}, {J::Spherical, 4, 3}, {J::Free, 7, 6},
                                                                  {J::Fixed, 0, 0}};
  for(const auto & [type, params, dof] : sizes)
    for(bool fwd : {true, false})
    {
      const J j(type, Vec3<T>(T(1), T(2), T(-2)), fwd, "j");
      EXPECT_EQ(j.params(), params);
      EXPECT_EQ(j.dof(), dof);
      EXPECT_EQ(j.motionSubspace().cols(), dof);
      EXPECT_MAT_NEAR(j.pose(j.zeroParam()).matrix(), Mat6<T>::Identity(), 0.0);
      EXPECT_EQ(static_cast<int>(j.zeroDof().size()), dof);
    }
  EXPECT_THROW(J(J::Rev, Vec3<T>::Zero(), true, "zero"), std::domain_error);
}

TYPED_TEST(JointTest, ForwardPosesMatchClosedForms)
{
  using T = TypeParam;
  using J = rbd::JointTpl<T>;
  const T q = T(0.83), d = T(-0.41), x = T(0.3), y = T(-0.7);
  // Rev about the unit axes: sva's RotX/Y/Z (Featherstone rx, ry, rz).
  EXPECT_MAT_NEAR(J(J::Rev, Vec3<T>::UnitX(), true, "").pose({q}).rotation(), sva::RotX(q), tol<T>());
  EXPECT_MAT_NEAR(J(J::Rev, Vec3<T>::UnitY(), true, "").pose({q}).rotation(), sva::RotY(q), tol<T>());
  EXPECT_MAT_NEAR(J(J::Rev, Vec3<T>::UnitZ(), true, "").pose({q}).rotation(), sva::RotZ(q), tol<T>());
  // rz(q) closed form: [c s 0; -s c 0; 0 0 1].
  Mat3<T> rz;
  rz << std::cos(q), std::sin(q), T(0), -std::sin(q), std::cos(q), T(0), T(0), T(0), T(1);
  EXPECT_MAT_NEAR(J(J::Rev, Vec3<T>::UnitZ(), true, "").pose({q}).rotation(), rz, tol<T>());

  const Vec3<T> a = Vec3<T>(T(1), T(-2), T(0.5)).normalized();
  const J rev(J::Rev, Vec3<T>(T(2), T(-4), T(1)), true, ""); // normalised by the joint
  EXPECT_MAT_NEAR(rev.axis(), a, tol<T>());
  EXPECT_MAT_NEAR(rev.pose({q}).rotation(), Mat3<T>(rodrigues(a, q).transpose()), tol<T>());
  EXPECT_MAT_NEAR(rev.pose({q}).translation(), Vec3<T>::Zero(), 0.0);

  const auto prism = J(J::Prism, a, true, "").pose({d});
  EXPECT_MAT_NEAR(prism.rotation(), Mat3<T>::Identity(), 0.0);
  EXPECT_MAT_NEAR(prism.translation(), Vec3<T>(a * d), tol<T>());

  const auto cyl = J(J::Cylindrical, a, true, "").pose({q, d});
  EXPECT_MAT_NEAR(cyl.rotation(), Mat3<T>(rodrigues(a, q).transpose()), tol<T>());
  EXPECT_MAT_NEAR(cyl.translation(), Vec3<T>(a * d), tol<T>());

  // Planar: (u, w, n) orthonormal right-handed, pose = rotation about n, translation R(n, q) (x u + y w)
  // (RBDyn: PTransform(RotZ(q), RotZ(q)^T (x, y, 0)), (x, y) in successor axes).
  const J planar(J::Planar, a, true, "");
  EXPECT_NEAR(static_cast<double>(planar.planeU().dot(a)), 0.0, tol<T>());
  EXPECT_NEAR(static_cast<double>(planar.planeU().norm()), 1.0, tol<T>());
  EXPECT_MAT_NEAR(planar.planeW(), Vec3<T>(a.cross(planar.planeU())), tol<T>());
  const auto pl = planar.pose({q, x, y});
  EXPECT_MAT_NEAR(pl.rotation(), Mat3<T>(rodrigues(a, q).transpose()), tol<T>());
  EXPECT_MAT_NEAR(pl.translation(), Vec3<T>(rodrigues(a, q) * (x * planar.planeU() + y * planar.planeW())), tol<T>());
  // the z normal of RBDyn: u = x, w = y, and its closed form
  const auto plz = J(J::Planar, Vec3<T>::UnitZ(), true, "").pose({q, x, y});
  EXPECT_MAT_NEAR(plz.rotation(), Mat3<T>(sva::RotZ(q)), tol<T>());
  EXPECT_MAT_NEAR(plz.translation(), Vec3<T>(std::cos(q) * x - std::sin(q) * y, std::sin(q) * x + std::cos(q) * y, T(0)),
                  tol<T>());
  EXPECT_NEAR(static_cast<double>(pl.translation().dot(a)), 0.0, tol<T>());

  // Spherical / Free: E = R(quat)^T; a non-unit quaternion stands for its normalisation.
  const T w = T(0.5), qx = T(-0.5), qy = T(0.7), qz = T(0.1);
  const T n = std::sqrt(w * w + qx * qx + qy * qy + qz * qz);
  const Mat3<T> R = quatRotation(w / n, qx / n, qy / n, qz / n);
  EXPECT_MAT_NEAR(J(J::Spherical, true, "").pose({w, qx, qy, qz}).rotation(), Mat3<T>(R.transpose()), tol<T>());
  const auto fr = J(J::Free, true, "").pose({w, qx, qy, qz, x, y, d});
  EXPECT_MAT_NEAR(fr.rotation(), Mat3<T>(R.transpose()), tol<T>());
  EXPECT_MAT_NEAR(fr.translation(), Vec3<T>(x, y, d), 0.0);

  // Motion subspaces of forward joints (constant, successor frame).
  Eigen::Matrix<T, 6, 1> sRev, sPrism;
  sRev << a, Vec3<T>::Zero();
  sPrism << Vec3<T>::Zero(), a;
  EXPECT_MAT_NEAR(rev.motionSubspace(), sRev, tol<T>());
  EXPECT_MAT_NEAR(J(J::Prism, a, true, "").motionSubspace(), sPrism, tol<T>());
  EXPECT_MAT_NEAR(J(J::Free, true, "").motionSubspace(), Mat6<T>::Identity(), 0.0);
}

// Backward joints: pose = forward pose inverse (checked on the 6x6 matrices), S = -X^-1 S_fwd.
TYPED_TEST(JointTest, BackwardIsInverseOfForward)
{
  using T = TypeParam;
  using J = rbd::JointTpl<T>;
  rbdtest::Rng rng(21);
  for(auto type : {J::Rev, J::Prism, J::Cylindrical, J::Planar, J::Spherical, J::Free, J::Fixed})
    for(int trial = 0; trial < 5; ++trial)
    {
      const Vec3<T> axis = rbdtest::randomUnit(rng).cast<T>();
      const J fwd(type, axis, true, "j"), bwd(type, axis, false, "j");
      const std::vector<T> q = randomParam(rng, fwd);
      const Mat6<T> Xf = fwd.pose(q).matrix();
      const Mat6<T> XfInv = Xf.inverse();
      EXPECT_MAT_NEAR(bwd.pose(q).matrix(), XfInv, 10 * tol<T>()) << rbd::jointTypeName(type);
      using S6 = Eigen::Matrix<T, 6, Eigen::Dynamic>;
      const S6 Sbwd = -XfInv * fwd.motionSubspace(), minusS = -fwd.motionSubspace();
      if(type == J::Fixed) // 6x0 (relErr takes no empty matrix)
      {
        EXPECT_EQ(bwd.motionSubspace(q).cols(), 0);
        continue;
      }
      EXPECT_MAT_NEAR(bwd.motionSubspace(q), Sbwd, 10 * tol<T>()) << rbd::jointTypeName(type);
      if(type == J::Rev || type == J::Prism || type == J::Cylindrical)
      {
        EXPECT_MAT_NEAR(bwd.motionSubspace(), minusS, 0.0);
      }
    }
}

// crm(S alpha) = -(dX/dt) X^-1 along the q(t) path of a constant alpha, by central differences,
// for forward and backward joints.
TYPED_TEST(JointTest, MotionSubspaceMatchesPoseDerivative)
{
  using T = TypeParam;
  using J = rbd::JointTpl<T>;
  const bool isDouble = std::is_same<T, double>::value;
  const T h = isDouble ? T(1e-5) : T(1e-6);
  const double fdTol = isDouble ? 1e-8 : 1e-10;
  rbdtest::Rng rng(22);
  for(auto type : {J::Rev, J::Prism, J::Cylindrical, J::Planar, J::Spherical, J::Free})
    for(bool fwd : {true, false})
      for(int trial = 0; trial < 4; ++trial)
      {
        const J j(type, rbdtest::randomUnit(rng).cast<T>(), fwd, "j");
        const std::vector<T> q = randomParam(rng, j);
        std::vector<T> a(static_cast<std::size_t>(j.dof()));
        for(auto & v : a) v = T(rbdtest::uniform(rng, -1.5, 1.5));
        const Mat6<T> dX = (j.pose(path(j, q, a, h)).matrix() - j.pose(path(j, q, a, -h)).matrix()) / (2 * h);
        const Mat6<T> expected = -dX * j.pose(q).matrix().inverse();
        Eigen::Matrix<T, 6, 1> v = Eigen::Matrix<T, 6, 1>::Zero();
        const auto S = j.motionSubspace(q);
        for(int k = 0; k < j.dof(); ++k) v += S.col(k) * a[static_cast<std::size_t>(k)];
        EXPECT_MAT_NEAR(crm<T>(v), expected, fdTol) << rbd::jointTypeName(type) << (fwd ? " forward" : " backward");
        if(j.constantMotionSubspace())
        {
          EXPECT_MAT_NEAR(j.motion(a).vector(), v, 0.0) << rbd::jointTypeName(type);
        }
      }
}
