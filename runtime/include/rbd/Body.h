#pragma once
// A rigid body: spatial inertia at the body origin, in body coordinates, and a unique name.

#include <ostream>
#include <string>
#include <utility>

#include <sva/SpaceVecAlg.h>

namespace rbd
{

template<typename T>
class BodyTpl
{
public:
  using Scalar = T;

  BodyTpl() : inertia_(T(0), sva::Vector3<T>::Zero(), sva::Matrix3<T>::Zero()) {}
  /// @param rbi Spatial inertia at the body origin, in body coordinates.
  BodyTpl(const sva::RBInertia<T> & rbi, std::string name) : inertia_(rbi), name_(std::move(name)) {}
  /// @param mass Mass (kg). @param com Centre of mass in body coordinates (m).
  /// @param inertia Rotational inertia at the body ORIGIN, in body coordinates (kg m^2).
  BodyTpl(T mass, const sva::Vector3<T> & com, const sva::Matrix3<T> & inertia, std::string name)
  : inertia_(mass, mass * com, inertia), name_(std::move(name))
  {
  }

  const sva::RBInertia<T> & inertia() const { return inertia_; }
  const std::string & name() const { return name_; }

  template<typename U>
  BodyTpl<U> cast() const
  {
    return BodyTpl<U>(inertia_.template cast<U>(), name_);
  }

  bool operator==(const BodyTpl & b) const { return name_ == b.name_ && inertia_ == b.inertia_; }
  bool operator!=(const BodyTpl & b) const { return !(*this == b); }

private:
  sva::RBInertia<T> inertia_;
  std::string name_;
};

using Body = BodyTpl<double>;

/// "Body: name" (RBDyn's format).
template<typename T>
std::ostream & operator<<(std::ostream & out, const BodyTpl<T> & b)
{
  return out << "Body: " << b.name();
}

} // namespace rbd
