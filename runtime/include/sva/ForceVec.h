// sva: spatial force vector f = [n; f] (couple first), Featherstone's F^6.
#pragma once

#include <ostream>

#include "fwd.h"

namespace sva
{

/// Spatial force vector f = [n; f]: couple n about the frame origin, linear force f.
/// The default constructor leaves the coefficients uninitialised, like Eigen.
template<class T>
class ForceVec
{
public:
  using scalar_type = T;
  using Scalar = T;
  using vector3_t = Vector3<T>;
  using vector6_t = Vector6<T>;

  /// Uninitialised (Eigen semantics).
  ForceVec() = default;
  /// From [n; f].
  ForceVec(const vector6_t & vec) : couple_(vec.template head<3>()), force_(vec.template tail<3>()) {}
  /// fv(n, f).
  ForceVec(const vector3_t & couplePart, const vector3_t & forcePart) : couple_(couplePart), force_(forcePart) {}

  static ForceVec Zero()
  {
    return ForceVec(vector3_t::Zero(), vector3_t::Zero());
  }

  const vector3_t & couple() const
  {
    return couple_;
  }
  vector3_t & couple()
  {
    return couple_;
  }
  const vector3_t & force() const
  {
    return force_;
  }
  vector3_t & force()
  {
    return force_;
  }

  /// [n; f] as an Eigen 6-vector.
  vector6_t vector() const
  {
    vector6_t ret;
    ret << couple_, force_;
    return ret;
  }

  /// f1 + f2
  ForceVec operator+(const ForceVec & fv) const
  {
    return ForceVec(couple_ + fv.couple_, force_ + fv.force_);
  }
  /// f1 - f2
  ForceVec operator-(const ForceVec & fv) const
  {
    return ForceVec(couple_ - fv.couple_, force_ - fv.force_);
  }
  /// -f
  ForceVec operator-() const
  {
    return ForceVec(-couple_, -force_);
  }
  ForceVec & operator+=(const ForceVec & fv)
  {
    couple_ += fv.couple_;
    force_ += fv.force_;
    return *this;
  }
  ForceVec & operator-=(const ForceVec & fv)
  {
    couple_ -= fv.couple_;
    force_ -= fv.force_;
    return *this;
  }
  /// f a
  ForceVec operator*(T scalar) const
  {
    return ForceVec(couple_ * scalar, force_ * scalar);
  }
  /// f / a
  ForceVec operator/(T scalar) const
  {
    return ForceVec(couple_ / scalar, force_ / scalar);
  }
  ForceVec & operator*=(T scalar)
  {
    couple_ *= scalar;
    force_ *= scalar;
    return *this;
  }
  ForceVec & operator/=(T scalar)
  {
    couple_ /= scalar;
    force_ /= scalar;
    return *this;
  }

  /// f . v = n . w + f . v
  T dot(const MotionVec<T> & mv) const
  {
    return couple_.dot(mv.angular()) + force_.dot(mv.linear());
  }

  template<class U>
  ForceVec<U> cast() const
  {
    return ForceVec<U>(couple_.template cast<U>(), force_.template cast<U>());
  }

  bool operator==(const ForceVec & fv) const
  {
    return couple_ == fv.couple_ && force_ == fv.force_;
  }
  bool operator!=(const ForceVec & fv) const
  {
    return !(*this == fv);
  }

  /// Eigen's relative comparison on [n; f].
  bool isApprox(const ForceVec & fv, T prec = Eigen::NumTraits<T>::dummy_precision()) const
  {
    return vector().isApprox(fv.vector(), prec);
  }

private:
  vector3_t couple_;
  vector3_t force_;
};

/// a f
template<class T>
inline ForceVec<T> operator*(detail::identity_t<T> scalar, const ForceVec<T> & fv)
{
  return fv * scalar;
}

template<class T>
inline std::ostream & operator<<(std::ostream & out, const ForceVec<T> & fv)
{
  out << fv.vector().transpose();
  return out;
}

} // namespace sva

// MotionVec and ForceVec refer to each other; make both complete for the user of either header.
#include "MotionVec.h"
