// sva: spatial vector algebra (Featherstone, "Rigid Body Dynamics Algorithms", appendix A).
// Eigen type aliases used throughout sva, templated on the scalar type.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sva
{

template<class T>
using Vector3 = Eigen::Matrix<T, 3, 1>;
template<class T>
using Matrix3 = Eigen::Matrix<T, 3, 3>;
template<class T>
using Vector6 = Eigen::Matrix<T, 6, 1>;
template<class T>
using Matrix6 = Eigen::Matrix<T, 6, 6>;
template<class T>
using Quaternion = Eigen::Quaternion<T>;
template<class T>
using AngleAxis = Eigen::AngleAxis<T>;

// Eigen has no 6d aliases; these are handy for the double case.
using Vector6d = Vector6<double>;
using Matrix6d = Matrix6<double>;

namespace detail
{
// Puts a parameter in a non-deduced context (std::type_identity is C++20).
template<class T>
struct identity
{
  using type = T;
};
template<class T>
using identity_t = typename identity<T>::type;

/// Evaluates an expression into the fixed-size type Plain (sizes checked by Eigen). The
/// destination is zeroed first: GCC 12 reports Eigen's debug-mode transpose aliasing check on a
/// fresh, uninitialised destination as a maybe-uninitialized use (e.g. `Matrix3d M(E.transpose())`).
template<class Plain, class Derived>
inline Plain toPlain(const Eigen::MatrixBase<Derived> & m)
{
  Plain ret = Plain::Zero();
  ret = m;
  return ret;
}
} // namespace detail

} // namespace sva

// SpaceVecAlg also declares its 6d aliases in namespace Eigen (code written for it says
// Eigen::Vector6d). Eigen 3.4 already has Vector3<T> and Matrix3<T>; older versions get ours.
namespace Eigen
{
template<class T>
using Vector6 = Matrix<T, 6, 1>;
template<class T>
using Matrix6 = Matrix<T, 6, 6>;
using Vector6d = Vector6<double>;
using Matrix6d = Matrix6<double>;
#if !EIGEN_VERSION_AT_LEAST(3, 4, 0)
template<class T>
using Vector3 = Matrix<T, 3, 1>;
template<class T>
using Matrix3 = Matrix<T, 3, 3>;
#endif
} // namespace Eigen
