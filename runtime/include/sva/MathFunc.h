// sva: the inverse of the right Jacobian of SO(3) and its time derivative (SpaceVecAlg's
// SO3RightJacInv, SO3RightJacInvDot; Solà et al., "A micro Lie theory for state estimation in
// robotics", eq. 144). sinc and sinc_inv are in EigenUtility.h.
//
//   Jr⁻¹(u) = 1 + u^/2 + f(|u|) u^²,            f(x) = 1/x² − (1 + cos x)/(2 x sin x)
//   d/dt Jr⁻¹(u) = du^/2 + (f'(x)/x)(u·du) u^² + f(x) (du^ u^ + u^ du^)
// Both closed forms are differences of terms ~ 1/x² (resp. 2/x³) much larger than f ~ 1/12
// (f' ~ x/360) for small x. With y = x/2 they are, exactly,
//   f(x) = N(y)/(4 y² sin y),        N(y) = sin y − y cos y = Σ_{k≥1} (−1)^(k+1) 2k y^(2k+1)/(2k+1)!
//   f'(x)/x = P(y)/(16 y⁴ sin² y),   P(y) = y² + y sin y cos y − 2 sin² y
//                                          = Σ_{m≥3} (−1)^(m−1) 4^(m−1) (2m − 4) y^(2m)/(2m)!
// and the series of N/y³ and P/y⁶ (factorial convergence, no cancellation) are used below y = 1.5.
#pragma once

#include <cmath>

#include "EigenTypedef.h"
#include "EigenUtility.h"

namespace sva
{

namespace detail
{

/// f(x) = 1/x² − (1 + cos x)/(2 x sin x) = (N(y)/y³)/(4 sinc y), y = x/2
template<class T>
inline T so3JacF(T x)
{
  using std::abs;
  using std::cos;
  using std::sin;
  const T y = abs(x) / T(2), y2 = y * y;
  T Ny3 = T(0);
  if(y < T(1.5))
  {
    T term = T(1); // y^(2k−2)/(2k+1)! times (−1)^(k+1), from k = 1
    for(int k = 1; k <= 14; ++k)
    {
      term /= T((2 * k) * (2 * k + 1));
      Ny3 += T(2 * k) * term;
      term *= -y2;
    }
  }
  else
    Ny3 = (sin(y) - y * cos(y)) / (y2 * y);
  return Ny3 / (T(4) * sinc(y));
}

/// f'(x)/x = (P(y)/y⁶)/(16 sinc² y), y = x/2
template<class T>
inline T so3JacDFOverX(T x)
{
  using std::abs;
  using std::cos;
  using std::sin;
  const T y = abs(x) / T(2), y2 = y * y;
  T Py6 = T(0);
  if(y < T(1.5))
  {
    T term = T(16) / T(720); // 4^(m−1) y^(2m−6)/(2m)! times (−1)^(m−1), from m = 3
    for(int m = 3; m <= 17; ++m)
    {
      Py6 += T(2 * m - 4) * term;
      term *= -T(4) * y2 / T((2 * m + 1) * (2 * m + 2));
    }
  }
  else
    Py6 = (y2 + y * sin(y) * cos(y) - T(2) * sin(y) * sin(y)) / (y2 * y2 * y2);
  const T s = sinc(y);
  return Py6 / (T(16) * s * s);
}

} // namespace detail

/// Jr⁻¹(u) = 1 + u^/2 + f(|u|) u^², the inverse of the right Jacobian of SO(3) at u.
template<class T>
inline Matrix3<T> SO3RightJacInv(const Vector3<T> & u)
{
  const Matrix3<T> ux = vector3ToCrossMatrix(u);
  return Matrix3<T>::Identity() + ux / T(2) + detail::so3JacF(u.norm()) * ux * ux;
}

/// d/dt Jr⁻¹(u) = du^/2 + (f'(|u|)/|u|)(u·du) u^² + f(|u|) (du^ u^ + u^ du^), du = d/dt u.
template<class T>
inline Matrix3<T> SO3RightJacInvDot(const Vector3<T> & u, const Vector3<T> & du)
{
  const Matrix3<T> ux = vector3ToCrossMatrix(u), dux = vector3ToCrossMatrix(du);
  const T x = u.norm();
  return dux / T(2) + detail::so3JacDFOverX(x) * u.dot(du) * ux * ux + detail::so3JacF(x) * (dux * ux + ux * dux);
}

} // namespace sva
