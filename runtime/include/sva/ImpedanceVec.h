// sva: mechanical impedance, f = Z v (SpaceVecAlg's ImpedanceVec): a diagonal map from motion to
// force, diag(angular, linear), f = [Za .* w; Zl .* v].
#pragma once

#include "DiagonalVec.h"
#include "ForceVec.h"
#include "MotionVec.h"

namespace sva
{

template<class T>
class ImpedanceVec : public detail::DiagonalVec<T, ImpedanceVec<T>>
{
public:
  using detail::DiagonalVec<T, ImpedanceVec<T>>::DiagonalVec;
  ImpedanceVec() = default;

  template<class U>
  ImpedanceVec<U> cast() const
  {
    return ImpedanceVec<U>(this->angular().template cast<U>(), this->linear().template cast<U>());
  }
};

/// Z v = [Za .* w; Zl .* v]
template<class T>
inline ForceVec<T> operator*(const ImpedanceVec<T> & z, const MotionVec<T> & mv)
{
  return ForceVec<T>(z.angular().cwiseProduct(mv.angular()), z.linear().cwiseProduct(mv.linear()));
}
template<class T>
inline ForceVec<T> operator*(const MotionVec<T> & mv, const ImpedanceVec<T> & z)
{
  return z * mv;
}

using ImpedanceVecd = ImpedanceVec<double>;

} // namespace sva
