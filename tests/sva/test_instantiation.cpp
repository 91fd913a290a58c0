// Every sva class template fully instantiated (all members compiled) for float, double and
// long double, plus a float smoke test of the whole API.
#include <sstream>

#include <gtest/gtest.h>

#include <sva/SpaceVecAlg.h>

template class sva::MotionVec<float>;
template class sva::ForceVec<float>;
template class sva::RBInertia<float>;
template class sva::ABInertia<float>;
template class sva::PTransform<float>;

template class sva::MotionVec<double>;
template class sva::ForceVec<double>;
template class sva::RBInertia<double>;
template class sva::ABInertia<double>;
template class sva::PTransform<double>;

template class sva::MotionVec<long double>;
template class sva::ForceVec<long double>;
template class sva::RBInertia<long double>;
template class sva::ABInertia<long double>;
template class sva::PTransform<long double>;

TEST(SvaFloat, WholeApiCompilesAndRuns)
{
  using T = float;
  using V3 = sva::Vector3<T>;
  using M3 = sva::Matrix3<T>;
  const V3 a(0.1f, -0.2f, 0.3f), b(-0.4f, 0.5f, 0.6f);
  const sva::MotionVecf v(a, b);
  const sva::ForceVecf f(b, a);
  const sva::RBInertiaf I(2.f, V3(0.2f, 0.f, 0.f), M3::Identity());
  const sva::ABInertiaf A = sva::toABInertia(I) + I;
  const sva::PTransformf X(sva::RotX(0.3f) * sva::RotY(-0.2f) * sva::RotZ(1.f), a);
  const sva::PTransformf Y(sva::Quaternion<T>(sva::AngleAxis<T>(0.5f, V3::UnitZ())), b);

  const sva::MotionVecf v2 = X * v + X.invMul(v) - v.cross(v) * 2.f;
  const sva::ForceVecf f2 = X.dualMul(f) + X.transMul(f) + v.crossDual(f) + I * v + A * v;
  const T p = v2.dot(f2) + f2.dot(v2);
  const sva::RBInertiaf I2 = X.dualMul(I) + X.transMul(I);
  const sva::ABInertiaf A2 = X.dualMul(A) + X.transMul(A) - I2;
  const sva::PTransformf Z = (X * Y).inv();
  const Eigen::Matrix<T, 6, Eigen::Dynamic> S = Eigen::Matrix<T, 6, Eigen::Dynamic>::Identity(6, 2);
  const Eigen::Matrix<T, 6, Eigen::Dynamic> S2 = X.mul(S) + X.invMul(S) + X.dualMul(S) + X.transMul(S);
  const V3 w = sva::rotationVelocity(Z.rotation()) + sva::rotationError(X.rotation(), Y.rotation());
  const sva::MotionVecf e = sva::transformVelocity(Z) + sva::transformError(X, Y);
  const M3 Io = sva::inertiaToOrigin(M3::Identity(), 1.f, a, X.rotation());
  const sva::PTransformf Xi = sva::interpolate(X, Y, 0.5f);
  const Eigen::Matrix<T, 4, 4> H = sva::conversions::toHomogeneous(Xi);
  const sva::PTransformf Xh = sva::conversions::fromHomogeneous(H);
  const sva::Matrix6<T> C = sva::vector6ToCrossMatrix(v) + sva::vector6ToCrossDualMatrix(v.vector());

  EXPECT_TRUE(std::isfinite(p));
  EXPECT_TRUE(I2.matrix().allFinite());
  EXPECT_TRUE(A2.matrix().allFinite());
  EXPECT_TRUE(S2.allFinite());
  EXPECT_TRUE(w.allFinite());
  EXPECT_TRUE(e.vector().allFinite());
  EXPECT_TRUE(Io.allFinite());
  EXPECT_TRUE(C.allFinite());
  EXPECT_TRUE(Xh.isApprox(Xi, 1e-5f));
  EXPECT_TRUE(((X * X.inv()).matrix() - sva::Matrix6<T>::Identity()).norm() < 1e-5f);
  EXPECT_TRUE(v.cast<double>().cast<float>() == v);

  std::ostringstream os;
  os << v << f << I << A << X;
  EXPECT_FALSE(os.str().empty());
}
