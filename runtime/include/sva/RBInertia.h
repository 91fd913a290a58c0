// sva: rigid-body spatial inertia, Featherstone rbi(m, h, I).
#pragma once

#include <algorithm>
#include <cmath>
#include <ostream>

#include "EigenUtility.h"
#include "ForceVec.h"
#include "MotionVec.h"
#include "fwd.h"

namespace sva
{

/// Rigid-body inertia rbi(m, h, I) = [I h^; h^T m1] = [I h^; -h^ m1] with mass m, first moment of
/// mass h = m c (c: CoM in body coordinates) and rotational inertia I at the body origin.
/// Only the lower triangle of the given I is read; the stored I is the symmetric matrix it
/// defines. Default construction gives the zero inertia.
template<class T>
class RBInertia
{
public:
  using scalar_type = T;
  using Scalar = T;
  using vector3_t = Vector3<T>;
  using matrix3_t = Matrix3<T>;
  using matrix6_t = Matrix6<T>;

  /// Zero inertia.
  RBInertia() : m_(T(0)), h_(vector3_t::Zero()), I_(matrix3_t::Zero()) {}
  /// rbi(m, h, I); `inertia` is the rotational inertia at the body origin (lower triangle read).
  RBInertia(T mass, const vector3_t & momentum, const matrix3_t & inertia)
  : m_(mass), h_(momentum), I_(inertia.template selfadjointView<Eigen::Lower>())
  {
  }

  static RBInertia Zero()
  {
    return RBInertia();
  }

  T mass() const
  {
    return m_;
  }
  /// h = m c
  const vector3_t & momentum() const
  {
    return h_;
  }
  /// Full symmetric rotational inertia at the body origin.
  const matrix3_t & inertia() const
  {
    return I_;
  }
  /// Lower triangle of inertia() (upper part zero).
  matrix3_t lowerTriangularInertia() const
  {
    return I_.template triangularView<Eigen::Lower>();
  }

  /// [I h^; -h^ m1]
  matrix6_t matrix() const
  {
    matrix6_t M;
    const matrix3_t hx = vector3ToCrossMatrix(h_);
    M.template topLeftCorner<3, 3>() = I_;
    M.template topRightCorner<3, 3>() = hx;
    M.template bottomLeftCorner<3, 3>() = -hx;
    M.template bottomRightCorner<3, 3>() = matrix3_t::Identity() * m_;
    return M;
  }

  /// I v = [I w + h x v; m v - h x w]
  ForceVec<T> operator*(const MotionVec<T> & mv) const
  {
    return ForceVec<T>(I_ * mv.angular() + h_.cross(mv.linear()), m_ * mv.linear() - h_.cross(mv.angular()));
  }

  /// I M for a 6xN matrix M of motion vectors (columns): [I Mw + h x Mv; m Mv - h x Mw]
  template<class Derived, class Result>
  void mul(const Eigen::MatrixBase<Derived> & M, const Eigen::MatrixBase<Result> & result) const
  {
    detail::columnwise<T>(M, result, [&](auto & R) {
      R.template topRows<3>() = I_ * motionAngular(M) + detail::crossColumns(h_, motionLinear(M));
      R.template bottomRows<3>() = m_ * motionLinear(M) - detail::crossColumns(h_, motionAngular(M));
    });
  }

  /// I1 + I2 = rbi(m1 + m2, h1 + h2, I1 + I2)
  RBInertia operator+(const RBInertia & rbi) const
  {
    return RBInertia(m_ + rbi.m_, h_ + rbi.h_, I_ + rbi.I_);
  }
  /// I1 - I2
  RBInertia operator-(const RBInertia & rbi) const
  {
    return RBInertia(m_ - rbi.m_, h_ - rbi.h_, I_ - rbi.I_);
  }
  /// -I
  RBInertia operator-() const
  {
    return RBInertia(-m_, -h_, -I_);
  }
  RBInertia & operator+=(const RBInertia & rbi)
  {
    m_ += rbi.m_;
    h_ += rbi.h_;
    I_ += rbi.I_;
    return *this;
  }
  RBInertia & operator-=(const RBInertia & rbi)
  {
    m_ -= rbi.m_;
    h_ -= rbi.h_;
    I_ -= rbi.I_;
    return *this;
  }
  /// I a
  RBInertia operator*(T scalar) const
  {
    return RBInertia(m_ * scalar, h_ * scalar, I_ * scalar);
  }

  template<class U>
  RBInertia<U> cast() const
  {
    return RBInertia<U>(static_cast<U>(m_), h_.template cast<U>(), I_.template cast<U>());
  }

  bool operator==(const RBInertia & rbi) const
  {
    return m_ == rbi.m_ && h_ == rbi.h_ && I_ == rbi.I_;
  }
  bool operator!=(const RBInertia & rbi) const
  {
    return !(*this == rbi);
  }

  /// Eigen's relative comparison, component by component (m, h, I).
  bool isApprox(const RBInertia & rbi, T prec = Eigen::NumTraits<T>::dummy_precision()) const
  {
    using std::abs;
    const bool massApprox = abs(m_ - rbi.m_) <= prec * std::min(abs(m_), abs(rbi.m_));
    return massApprox && h_.isApprox(rbi.h_, prec) && I_.isApprox(rbi.I_, prec);
  }

private:
  T m_;
  vector3_t h_;
  matrix3_t I_;
};

/// a I
template<class T>
inline RBInertia<T> operator*(detail::identity_t<T> scalar, const RBInertia<T> & rbi)
{
  return rbi * scalar;
}

template<class T>
inline std::ostream & operator<<(std::ostream & out, const RBInertia<T> & rbi)
{
  out << rbi.matrix();
  return out;
}

} // namespace sva
