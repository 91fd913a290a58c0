// sva: the storage and arithmetic shared by ImpedanceVec and AdmittanceVec: a diagonal spatial
// matrix diag(angular, linear), stored as its two 3-vector diagonals (SpaceVecAlg's layout).
#pragma once

#include <ostream>
#include <type_traits>

#include "EigenTypedef.h"

namespace sva
{
namespace detail
{

/// diag(a, l): 6 diagonal coefficients, angular part first. Derived is the concrete class
/// (CRTP), so that the operators return it.
template<class T, class Derived>
class DiagonalVec
{
public:
  using scalar_type = T;
  using Scalar = T;
  using vector3_t = Vector3<T>;
  using vector6_t = Vector6<T>;

  /// Uninitialised (Eigen semantics).
  DiagonalVec() = default;
  /// From [a; l].
  DiagonalVec(const vector6_t & vec) : angular_(vec.template head<3>()), linear_(vec.template tail<3>()) {}
  DiagonalVec(const vector3_t & angularPart, const vector3_t & linearPart) : angular_(angularPart), linear_(linearPart)
  {
  }
  /// The same coefficient on the three angular, and on the three linear, axes.
  DiagonalVec(T angularPart, T linearPart) : angular_(vector3_t::Constant(angularPart)), linear_(vector3_t::Constant(linearPart))
  {
  }

  static Derived Zero()
  {
    return Derived(vector3_t::Zero(), vector3_t::Zero());
  }

  const vector3_t & angular() const { return angular_; }
  vector3_t & angular() { return angular_; }
  const vector3_t & linear() const { return linear_; }
  vector3_t & linear() { return linear_; }
  /// [a; l]
  vector6_t vector() const { return (vector6_t() << angular_, linear_).finished(); }

  Derived operator+(const Derived & o) const
  {
    return Derived(angular_ + o.angular(), linear_ + o.linear());
  }
  Derived & operator+=(const Derived & o)
  {
    angular_ += o.angular();
    linear_ += o.linear();
    return self();
  }
  Derived operator*(T scalar) const
  {
    return Derived(angular_ * scalar, linear_ * scalar);
  }
  Derived & operator*=(T scalar)
  {
    angular_ *= scalar;
    linear_ *= scalar;
    return self();
  }
  Derived operator/(T scalar) const
  {
    return Derived(angular_ / scalar, linear_ / scalar);
  }
  Derived & operator/=(T scalar)
  {
    angular_ /= scalar;
    linear_ /= scalar;
    return self();
  }
  bool operator==(const Derived & o) const
  {
    return angular_ == o.angular() && linear_ == o.linear();
  }
  bool operator!=(const Derived & o) const
  {
    return !(*this == o);
  }

  /// a * diag(a, l)
  friend Derived operator*(T scalar, const Derived & d)
  {
    return d * scalar;
  }
  friend std::ostream & operator<<(std::ostream & out, const Derived & d)
  {
    return out << d.vector().transpose();
  }

private:
  Derived & self()
  {
    return static_cast<Derived &>(*this);
  }

  vector3_t angular_;
  vector3_t linear_;
};

} // namespace detail
} // namespace sva
