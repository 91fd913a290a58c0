// sva: mechanical admittance, v = A f (SpaceVecAlg's AdmittanceVec), the reciprocal of impedance:
// a diagonal map from force to motion, diag(angular, linear), v = [Aa .* n; Al .* f].
#pragma once

#include "DiagonalVec.h"
#include "ForceVec.h"
#include "MotionVec.h"

namespace sva
{

template<class T>
class AdmittanceVec : public detail::DiagonalVec<T, AdmittanceVec<T>>
{
public:
  using detail::DiagonalVec<T, AdmittanceVec<T>>::DiagonalVec;
  AdmittanceVec() = default;

  template<class U>
  AdmittanceVec<U> cast() const
  {
    return AdmittanceVec<U>(this->angular().template cast<U>(), this->linear().template cast<U>());
  }
};

/// A f = [Aa .* n; Al .* f]
template<class T>
inline MotionVec<T> operator*(const AdmittanceVec<T> & a, const ForceVec<T> & fv)
{
  return MotionVec<T>(a.angular().cwiseProduct(fv.couple()), a.linear().cwiseProduct(fv.force()));
}
template<class T>
inline MotionVec<T> operator*(const ForceVec<T> & fv, const AdmittanceVec<T> & a)
{
  return a * fv;
}

using AdmittanceVecd = AdmittanceVec<double>;

} // namespace sva
