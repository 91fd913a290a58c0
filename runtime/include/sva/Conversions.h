// sva: conversions between PTransform and homogeneous matrices / Eigen affine transforms.
#pragma once

#include <type_traits>

#include "PTransform.h"

namespace sva
{
namespace conversions
{

/// Handedness tags. RightHanded: the usual convention, the rotation block is the rotation of B in
/// A (E^T for sva). LeftHanded: the rotation block is sva's E itself.
inline constexpr bool RightHanded = true;
inline constexpr bool LeftHanded = false;

/// X_a_b = plx(E, r) -> [E^T r; 0 1] (right-handed: maps B coordinates of a point to A
/// coordinates) or [E r; 0 1] (left-handed).
template<class T>
inline Eigen::Matrix<T, 4, 4> toHomogeneous(const PTransform<T> & X, bool rightHandedness = RightHanded)
{
  Eigen::Matrix<T, 4, 4> H = Eigen::Matrix<T, 4, 4>::Identity();
  if(rightHandedness)
  {
    H.template topLeftCorner<3, 3>() = X.rotation().transpose();
  }
  else
  {
    H.template topLeftCorner<3, 3>() = X.rotation();
  }
  H.template topRightCorner<3, 1>() = X.translation();
  return H;
}

/// Inverse of toHomogeneous (the last row of H is ignored).
template<class T>
inline PTransform<T> fromHomogeneous(const Eigen::Matrix<T, 4, 4> & H, bool rightHandedness = RightHanded)
{
  Matrix3<T> E = H.template topLeftCorner<3, 3>();
  if(rightHandedness)
  {
    E.transposeInPlace();
  }
  return PTransform<T>(E, Vector3<T>(H.template topRightCorner<3, 1>()));
}

/// X_a_b -> Eigen affine transform with linear() = E^T (right-handed) or E, translation() = r.
template<class T>
inline Eigen::Transform<T, 3, Eigen::Affine> toAffine(const PTransform<T> & X, bool rightHandedness = RightHanded)
{
  Eigen::Transform<T, 3, Eigen::Affine> A = Eigen::Transform<T, 3, Eigen::Affine>::Identity();
  if(rightHandedness)
  {
    A.linear() = X.rotation().transpose();
  }
  else
  {
    A.linear() = X.rotation();
  }
  A.translation() = X.translation();
  return A;
}

/// Inverse of toAffine; accepts Affine, AffineCompact and Isometry transforms.
template<class T, int Mode, int Options>
inline PTransform<T> fromAffine(const Eigen::Transform<T, 3, Mode, Options> & A, bool rightHandedness = RightHanded)
{
  static_assert(Mode == Eigen::Affine || Mode == Eigen::AffineCompact || Mode == Eigen::Isometry,
                "sva::conversions::fromAffine: projective transforms are not supported");
  Matrix3<T> E = A.linear();
  if(rightHandedness)
  {
    E.transposeInPlace();
  }
  return PTransform<T>(E, Vector3<T>(A.translation()));
}

} // namespace conversions
} // namespace sva
