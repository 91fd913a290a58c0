// sva: free functions on Eigen types: cross-product matrices, elementary rotations (Featherstone
// rx/ry/rz), the rotation log map, rotation error and the parallel-axis theorem.
//
// Functions taking Eigen matrices have an exact overload (Matrix3<T>, Vector3<T>, ...) and an
// overload taking any Eigen expression of the right size (e.g. `vector3ToCrossMatrix(E * r)`).
#pragma once

#include <cmath>

#include "EigenTypedef.h"
#include "MotionVec.h"

namespace sva
{

// ---------------------------------------------------------------------------------------------
// Cross-product matrices

/// v^ (3x3 skew matrix, v^ u = v x u) = [0 -vz vy; vz 0 -vx; -vy vx 0]
template<class T>
inline Matrix3<T> vector3ToCrossMatrix(const Vector3<T> & v)
{
  Matrix3<T> m;
  m << T(0), -v.z(), v.y(), v.z(), T(0), -v.x(), -v.y(), v.x(), T(0);
  return m;
}

template<class Derived>
inline Matrix3<typename Derived::Scalar> vector3ToCrossMatrix(const Eigen::MatrixBase<Derived> & v)
{
  return vector3ToCrossMatrix(detail::toPlain<Vector3<typename Derived::Scalar>>(v));
}

/// crm(v) = [w^ 0; v^ w^] for v = [w; v] (motion cross product: v x m = crm(v) m)
template<class T>
inline Matrix6<T> vector6ToCrossMatrix(const Vector6<T> & v)
{
  const Matrix3<T> wx = vector3ToCrossMatrix(Vector3<T>(v.template head<3>()));
  Matrix6<T> m;
  m.template topLeftCorner<3, 3>() = wx;
  m.template topRightCorner<3, 3>().setZero();
  m.template bottomLeftCorner<3, 3>() = vector3ToCrossMatrix(Vector3<T>(v.template tail<3>()));
  m.template bottomRightCorner<3, 3>() = wx;
  return m;
}

template<class Derived>
inline Matrix6<typename Derived::Scalar> vector6ToCrossMatrix(const Eigen::MatrixBase<Derived> & v)
{
  return vector6ToCrossMatrix(detail::toPlain<Vector6<typename Derived::Scalar>>(v));
}

template<class T>
inline Matrix6<T> vector6ToCrossMatrix(const MotionVec<T> & v)
{
  return vector6ToCrossMatrix(v.vector());
}

/// crf(v) = -crm(v)^T = [w^ v^; 0 w^] (force cross product: v x* f = crf(v) f)
template<class T>
inline Matrix6<T> vector6ToCrossDualMatrix(const Vector6<T> & v)
{
  const Matrix3<T> wx = vector3ToCrossMatrix(Vector3<T>(v.template head<3>()));
  Matrix6<T> m;
  m.template topLeftCorner<3, 3>() = wx;
  m.template topRightCorner<3, 3>() = vector3ToCrossMatrix(Vector3<T>(v.template tail<3>()));
  m.template bottomLeftCorner<3, 3>().setZero();
  m.template bottomRightCorner<3, 3>() = wx;
  return m;
}

template<class Derived>
inline Matrix6<typename Derived::Scalar> vector6ToCrossDualMatrix(const Eigen::MatrixBase<Derived> & v)
{
  return vector6ToCrossDualMatrix(detail::toPlain<Vector6<typename Derived::Scalar>>(v));
}

template<class T>
inline Matrix6<T> vector6ToCrossDualMatrix(const MotionVec<T> & v)
{
  return vector6ToCrossDualMatrix(v.vector());
}

// ---------------------------------------------------------------------------------------------
// Elementary rotations: Featherstone rx, ry, rz, i.e. the TRANSPOSE of the usual rotation matrix
// (they map coordinates of the fixed frame into the rotated frame).

/// rx(t) = [1 0 0; 0 c s; 0 -s c]
template<class T>
inline Matrix3<T> RotX(T theta)
{
  using std::cos;
  using std::sin;
  const T c = cos(theta), s = sin(theta);
  Matrix3<T> m;
  m << T(1), T(0), T(0), T(0), c, s, T(0), -s, c;
  return m;
}

/// ry(t) = [c 0 -s; 0 1 0; s 0 c]
template<class T>
inline Matrix3<T> RotY(T theta)
{
  using std::cos;
  using std::sin;
  const T c = cos(theta), s = sin(theta);
  Matrix3<T> m;
  m << c, T(0), -s, T(0), T(1), T(0), s, T(0), c;
  return m;
}

/// rz(t) = [c s 0; -s c 0; 0 0 1]
template<class T>
inline Matrix3<T> RotZ(T theta)
{
  using std::cos;
  using std::sin;
  const T c = cos(theta), s = sin(theta);
  Matrix3<T> m;
  m << c, s, T(0), -s, c, T(0), T(0), T(0), T(1);
  return m;
}

// ---------------------------------------------------------------------------------------------
// sinc helpers

/// sin(x) / x, continuous at 0 (Taylor 1 - x^2/6 + x^4/120 near 0).
template<class T>
inline T sinc(T x)
{
  using std::abs;
  using std::sin;
  using std::sqrt;
  if(abs(x) < sqrt(sqrt(Eigen::NumTraits<T>::epsilon())))
  {
    const T x2 = x * x;
    return T(1) - x2 / T(6) + x2 * x2 / T(120);
  }
  return sin(x) / x;
}

/// x / sin(x), continuous at 0 (Taylor 1 + x^2/6 + 7 x^4/360 near 0).
template<class T>
inline T sinc_inv(T x)
{
  using std::abs;
  using std::sin;
  using std::sqrt;
  if(abs(x) < sqrt(sqrt(Eigen::NumTraits<T>::epsilon())))
  {
    const T x2 = x * x;
    return T(1) + x2 / T(6) + T(7) * x2 * x2 / T(360);
  }
  return x / sin(x);
}

// ---------------------------------------------------------------------------------------------
// Rotation log map and rotation error

/// Log map of an sva rotation: returns w = theta * a such that E_a_b = R(a, theta)^T (the
/// transpose of the usual rotation about unit axis a by theta in [0, pi]); w = log(E^T).
/// theta = atan2(|s|, (tr E - 1)/2) with s = vee(E^T - E)/2 = sin(theta) a (accurate at 0 and pi).
/// For theta < 2pi/3 the axis comes from the antisymmetric part (w = s theta / sin theta), beyond
/// from the symmetric part (E + E^T)/2 = cos(theta) 1 + (1 - cos(theta)) a a^T, sign taken from s.
template<class T>
inline Vector3<T> rotationVelocity(const Matrix3<T> & E_a_b)
{
  using std::atan2;
  using std::sqrt;
  const Vector3<T> s =
      T(0.5)
      * Vector3<T>(E_a_b(1, 2) - E_a_b(2, 1), E_a_b(2, 0) - E_a_b(0, 2), E_a_b(0, 1) - E_a_b(1, 0));
  const T sinTheta = s.norm();
  const T cosTheta = (E_a_b.trace() - T(1)) * T(0.5);
  const T theta = atan2(sinTheta, cosTheta);

  if(cosTheta > T(-0.5))
  {
    // theta in [0, 2pi/3): theta / sin(theta) in [1, 2.42].
    if(sinTheta == T(0))
    {
      return Vector3<T>::Zero();
    }
    return s * (theta / sinTheta);
  }

  // theta in [2pi/3, pi]: a a^T = ((E + E^T)/2 - cos(theta) 1) / (1 - cos(theta)).
  Matrix3<T> aaT = (E_a_b + E_a_b.transpose()) * T(0.5);
  aaT.diagonal().array() -= cosTheta;
  aaT /= (T(1) - cosTheta);
  Eigen::Index k = 0;
  aaT.diagonal().maxCoeff(&k); // a_k^2 >= 1/3
  Vector3<T> axis = aaT.col(k) / sqrt(aaT(k, k));
  axis.normalize();
  if(axis.dot(s) < T(0))
  {
    axis = -axis;
  }
  return theta * axis;
}

template<class Derived>
inline Vector3<typename Derived::Scalar> rotationVelocity(const Eigen::MatrixBase<Derived> & E_a_b)
{
  return rotationVelocity(detail::toPlain<Matrix3<typename Derived::Scalar>>(E_a_b));
}

/// Rotation error from E_a_b to E_a_c as an axis * angle vector expressed in frame a:
/// E_b_c = E_a_c E_a_b^T, error = E_a_b^T rotationVelocity(E_b_c).
template<class T>
inline Vector3<T> rotationError(const Matrix3<T> & E_a_b, const Matrix3<T> & E_a_c)
{
  const Matrix3<T> E_b_c = E_a_c * E_a_b.transpose();
  return E_a_b.transpose() * rotationVelocity(E_b_c);
}

template<class Derived1, class Derived2>
inline Vector3<typename Derived1::Scalar> rotationError(const Eigen::MatrixBase<Derived1> & E_a_b,
                                                       const Eigen::MatrixBase<Derived2> & E_a_c)
{
  using T = typename Derived1::Scalar;
  return rotationError(detail::toPlain<Matrix3<T>>(E_a_b), detail::toPlain<Matrix3<T>>(E_a_c));
}

// ---------------------------------------------------------------------------------------------
// Parallel-axis theorem

/// Rotational inertia at the body origin from the inertia I_c at the CoM, expressed in a frame of
/// rotation `rotation` (mapping CoM-frame coordinates into body coordinates), mass m and CoM c:
/// I_O = E I_c E^T + m c^ c^T  (Featherstone mcI: I_O = I_c + m c^ c^T).
template<class T>
inline Matrix3<T> inertiaToOrigin(const Matrix3<T> & inertia,
                                  detail::identity_t<T> mass,
                                  const Vector3<T> & com,
                                  const Matrix3<T> & rotation)
{
  const Matrix3<T> cx = vector3ToCrossMatrix(com);
  return rotation * inertia * rotation.transpose() + mass * cx * cx.transpose();
}

template<class Derived1, class Derived2, class Derived3>
inline Matrix3<typename Derived1::Scalar> inertiaToOrigin(const Eigen::MatrixBase<Derived1> & inertia,
                                                         typename Derived1::Scalar mass,
                                                         const Eigen::MatrixBase<Derived2> & com,
                                                         const Eigen::MatrixBase<Derived3> & rotation)
{
  using T = typename Derived1::Scalar;
  return inertiaToOrigin(detail::toPlain<Matrix3<T>>(inertia), mass, detail::toPlain<Vector3<T>>(com),
                         detail::toPlain<Matrix3<T>>(rotation));
}

} // namespace sva
