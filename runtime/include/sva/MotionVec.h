// sva: spatial motion vector v = [w; v] (angular part first), Featherstone's M^6.
#pragma once

#include <ostream>

#include "Columns.h"
#include "fwd.h"

namespace sva
{

/// Spatial motion vector v = [w; v]: angular part w, linear part v (velocity of the point at the
/// frame origin). The default constructor leaves the coefficients uninitialised, like Eigen.
template<class T>
class MotionVec
{
public:
  using scalar_type = T;
  using Scalar = T;
  using vector3_t = Vector3<T>;
  using vector6_t = Vector6<T>;

  /// Uninitialised (Eigen semantics).
  MotionVec() = default;
  /// From [w; v].
  MotionVec(const vector6_t & vec) : angular_(vec.template head<3>()), linear_(vec.template tail<3>()) {}
  /// mv(w, v).
  MotionVec(const vector3_t & angularPart, const vector3_t & linearPart) : angular_(angularPart), linear_(linearPart)
  {
  }

  static MotionVec Zero()
  {
    return MotionVec(vector3_t::Zero(), vector3_t::Zero());
  }

  const vector3_t & angular() const
  {
    return angular_;
  }
  vector3_t & angular()
  {
    return angular_;
  }
  const vector3_t & linear() const
  {
    return linear_;
  }
  vector3_t & linear()
  {
    return linear_;
  }

  /// [w; v] as an Eigen 6-vector.
  vector6_t vector() const
  {
    vector6_t ret;
    ret << angular_, linear_;
    return ret;
  }

  /// v1 + v2
  MotionVec operator+(const MotionVec & mv) const
  {
    return MotionVec(angular_ + mv.angular_, linear_ + mv.linear_);
  }
  /// v1 - v2
  MotionVec operator-(const MotionVec & mv) const
  {
    return MotionVec(angular_ - mv.angular_, linear_ - mv.linear_);
  }
  /// -v
  MotionVec operator-() const
  {
    return MotionVec(-angular_, -linear_);
  }
  MotionVec & operator+=(const MotionVec & mv)
  {
    angular_ += mv.angular_;
    linear_ += mv.linear_;
    return *this;
  }
  MotionVec & operator-=(const MotionVec & mv)
  {
    angular_ -= mv.angular_;
    linear_ -= mv.linear_;
    return *this;
  }
  /// v a
  MotionVec operator*(T scalar) const
  {
    return MotionVec(angular_ * scalar, linear_ * scalar);
  }
  /// v / a
  MotionVec operator/(T scalar) const
  {
    return MotionVec(angular_ / scalar, linear_ / scalar);
  }
  MotionVec & operator*=(T scalar)
  {
    angular_ *= scalar;
    linear_ *= scalar;
    return *this;
  }
  MotionVec & operator/=(T scalar)
  {
    angular_ /= scalar;
    linear_ /= scalar;
    return *this;
  }

  /// v1 x v2 = crm(v1) v2 = [w1 x w2; w1 x v2 + v1 x w2]
  MotionVec cross(const MotionVec & mv) const
  {
    return MotionVec(angular_.cross(mv.angular_), angular_.cross(mv.linear_) + linear_.cross(mv.angular_));
  }

  /// v x* f = crf(v) f = -crm(v)^T f = [w x n + v x f; w x f]
  ForceVec<T> crossDual(const ForceVec<T> & fv) const
  {
    return ForceVec<T>(angular_.cross(fv.couple()) + linear_.cross(fv.force()), angular_.cross(fv.force()));
  }

  /// crm(v) M for a 6xN matrix M of motion vectors (columns): [w x Mw; w x Mv + v x Mw]
  template<class Derived, class Result>
  void cross(const Eigen::MatrixBase<Derived> & M, const Eigen::MatrixBase<Result> & result) const
  {
    detail::columnwise<T>(M, result, [&](auto & R) {
      R.template topRows<3>() = detail::crossColumns(angular_, motionAngular(M));
      R.template bottomRows<3>() =
          detail::crossColumns(angular_, motionLinear(M)) + detail::crossColumns(linear_, motionAngular(M));
    });
  }

  /// crf(v) M for a 6xN matrix M of force vectors (columns): [w x Mn + v x Mf; w x Mf]
  template<class Derived, class Result>
  void crossDual(const Eigen::MatrixBase<Derived> & M, const Eigen::MatrixBase<Result> & result) const
  {
    detail::columnwise<T>(M, result, [&](auto & R) {
      R.template topRows<3>() =
          detail::crossColumns(angular_, forceCouple(M)) + detail::crossColumns(linear_, forceForce(M));
      R.template bottomRows<3>() = detail::crossColumns(angular_, forceForce(M));
    });
  }

  /// v . f = w . n + v . f
  T dot(const ForceVec<T> & fv) const
  {
    return angular_.dot(fv.couple()) + linear_.dot(fv.force());
  }

  template<class U>
  MotionVec<U> cast() const
  {
    return MotionVec<U>(angular_.template cast<U>(), linear_.template cast<U>());
  }

  bool operator==(const MotionVec & mv) const
  {
    return angular_ == mv.angular_ && linear_ == mv.linear_;
  }
  bool operator!=(const MotionVec & mv) const
  {
    return !(*this == mv);
  }

  /// Eigen's relative comparison on [w; v] (so nothing but an exact zero is approx. a zero vector).
  bool isApprox(const MotionVec & mv, T prec = Eigen::NumTraits<T>::dummy_precision()) const
  {
    return vector().isApprox(mv.vector(), prec);
  }

private:
  vector3_t angular_;
  vector3_t linear_;
};

/// a v
template<class T>
inline MotionVec<T> operator*(detail::identity_t<T> scalar, const MotionVec<T> & mv)
{
  return mv * scalar;
}

template<class T>
inline std::ostream & operator<<(std::ostream & out, const MotionVec<T> & mv)
{
  out << mv.vector().transpose();
  return out;
}

} // namespace sva

// MotionVec and ForceVec refer to each other; make both complete for the user of either header.
#include "ForceVec.h"
