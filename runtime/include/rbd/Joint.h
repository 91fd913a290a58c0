#pragma once
// Joint models: pose X_j(q), motion subspace S, joint velocity S*alpha (see docs/DESIGN.md).
//
// Forward joints have a motion subspace that is constant in the successor frame. A backward joint
// (forward() == false) keeps the q and alpha of its forward twin, which describe the predecessor
// side moving w.r.t. the successor side, so
//   X_j_bwd(q) = X_j_fwd(q)^-1,   S_bwd(q) = -X_j_fwd(q)^-1 S_fwd,   d/dt(S_bwd) alpha = 0.

#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <sva/SpaceVecAlg.h>

namespace rbd
{

/// Joint types, shared by every scalar type (so that `rbd::Joint::Rev` reads as in RBDyn).
struct JointType
{
  enum Type
  {
    Rev,
    Prism,
    Spherical,
    Planar,
    Cylindrical,
    Free,
    Fixed
  };
  /// RBDyn's older axis-named types: Joint(Joint::RevX, forward, name) is a Rev joint about x.
  enum OldType
  {
    RevX,
    RevY,
    RevZ,
    PrismX,
    PrismY,
    PrismZ
  };
};

const char * jointTypeName(JointType::Type t);

template<typename T>
class JointTpl : public JointType
{
public:
  using Scalar = T;
  using MotionSubspace = Eigen::Matrix<T, 6, Eigen::Dynamic>;

  JointTpl() : JointTpl(Fixed, true, "") {}
  /// @param axis Joint axis for Rev, Prism and Cylindrical; plane normal for Planar (normalised
  ///        here; must not be zero). Ignored by Spherical, Free and Fixed.
  JointTpl(Type type, const sva::Vector3<T> & axis, bool forward, std::string name)
  : type_(type), forward_(forward), name_(std::move(name))
  {
    construct(axis);
  }
  JointTpl(Type type, bool forward, std::string name)
  : JointTpl(type, sva::Vector3<T>::UnitZ(), forward, std::move(name))
  {
  }
  /// RevX..PrismZ: a Rev or Prism joint about a unit axis of the frame.
  JointTpl(OldType type, bool forward, std::string name)
  : JointTpl(type <= RevZ ? Rev : Prism, sva::Vector3<T>::Unit(static_cast<int>(type) % 3), forward, std::move(name))
  {
  }
  /// A Fixed joint.
  explicit JointTpl(std::string name) : JointTpl(Fixed, true, std::move(name)) {}

  Type type() const { return type_; }
  const std::string & name() const { return name_; }
  bool forward() const { return forward_; }
  /// Change the direction (used when a graph is rooted on the other side of the joint).
  void forward(bool f) { forward_ = f; }
  /// +1 for a forward joint, -1 for a backward one.
  T direction() const { return forward_ ? T(1) : T(-1); }
  /// Unit axis (Rev, Prism, Cylindrical) or plane normal (Planar).
  const sva::Vector3<T> & axis() const { return axis_; }
  /// In-plane basis of a Planar joint (x along planeU, y along planeW, in the successor's axes).
  const sva::Vector3<T> & planeU() const { return u_; }
  const sva::Vector3<T> & planeW() const { return w_; }

  /// Size of q for this joint.
  int params() const { return params_; }
  /// Size of alpha for this joint.
  int dof() const { return dof_; }
  /// True when S does not depend on q (every forward joint, backward Rev/Prism/Cylindrical/Fixed).
  bool constantMotionSubspace() const
  {
    return forward_ || type_ == Rev || type_ == Prism || type_ == Cylindrical || type_ == Fixed;
  }

  /// Forward motion subspace S_fwd (6 x dof), in the successor frame.
  const MotionSubspace & forwardMotionSubspace() const { return S_; }
  /// Motion subspace; exact whenever constantMotionSubspace(), else the value at q = zeroParam().
  MotionSubspace motionSubspace() const { return forward_ ? S_ : MotionSubspace(-S_); }
  /// Motion subspace at configuration q (exact for every joint and direction).
  MotionSubspace motionSubspace(const std::vector<T> & q) const
  {
    if(constantMotionSubspace()) return motionSubspace();
    // S_bwd = -X_fwd(q)^-1 S_fwd
    return -forwardPose(q).inv().mul(S_);
  }

  /// Joint transform X_j(q): from the joint's predecessor frame to its successor frame.
  sva::PTransform<T> pose(const std::vector<T> & q) const
  {
    if(forward_) return forwardPose(q);
    switch(type_)
    {
      case Rev:
      case Prism:
      case Cylindrical:
      case Fixed:
        return forwardPose(negated(q));
      default:
        return forwardPose(q).inv();
    }
  }

  /// Joint velocity S alpha (exact whenever constantMotionSubspace()).
  sva::MotionVec<T> motion(const std::vector<T> & alpha) const { return sva::MotionVec<T>(apply(alpha)); }
  /// Tangential acceleration S alphaD (exact whenever constantMotionSubspace()).
  sva::MotionVec<T> tanAccel(const std::vector<T> & alphaD) const
  {
    return sva::MotionVec<T>(apply(alphaD));
  }

  /// Identity configuration: zeros, quaternions = (1, 0, 0, 0).
  std::vector<T> zeroParam() const
  {
    std::vector<T> q(static_cast<std::size_t>(params_), T(0));
    if(type_ == Spherical || type_ == Free) q[0] = T(1);
    return q;
  }
  std::vector<T> zeroDof() const { return std::vector<T>(static_cast<std::size_t>(dof_), T(0)); }
  /// zeroParam() / zeroDof() of a joint of this type.
  static std::vector<T> ZeroParam(Type type) { return JointTpl(type, true, "").zeroParam(); }
  static std::vector<T> ZeroDof(Type type) { return JointTpl(type, true, "").zeroDof(); }

  /// Checked variants: throw std::domain_error unless q has params() / alpha has dof() values.
  sva::PTransform<T> sPose(const std::vector<T> & q) const { return pose(checked(q, params_, "position")); }
  sva::MotionVec<T> sMotion(const std::vector<T> & alpha) const { return motion(checked(alpha, dof_, "velocity")); }
  sva::MotionVec<T> sTanAccel(const std::vector<T> & alphaD) const
  {
    return tanAccel(checked(alphaD, dof_, "acceleration"));
  }

  template<typename U>
  JointTpl<U> cast() const
  {
    return JointTpl<U>(type_, axis_.template cast<U>(), forward_, name_);
  }

  bool operator==(const JointTpl & j) const
  {
    return type_ == j.type_ && forward_ == j.forward_ && name_ == j.name_ && axis_ == j.axis_;
  }
  bool operator!=(const JointTpl & j) const { return !(*this == j); }

private:
  void construct(const sva::Vector3<T> & axis);
  sva::PTransform<T> forwardPose(const std::vector<T> & q) const;
  Eigen::Matrix<T, 6, 1> apply(const std::vector<T> & v) const
  {
    const MotionSubspace S = motionSubspace();
    Eigen::Matrix<T, 6, 1> out = Eigen::Matrix<T, 6, 1>::Zero();
    for(int k = 0; k < dof_; ++k) out += S.col(k) * v[static_cast<std::size_t>(k)];
    return out;
  }
  const std::vector<T> & checked(const std::vector<T> & v, int size, const char * what) const
  {
    if(static_cast<int>(v.size()) != size)
      throw std::domain_error("joint '" + name_ + "': " + std::to_string(v.size()) + " generalized " + what +
                              " values, expected " + std::to_string(size));
    return v;
  }
  static std::vector<T> negated(std::vector<T> q)
  {
    for(T & x : q) x = -x;
    return q;
  }

  Type type_;
  bool forward_;
  std::string name_;
  sva::Vector3<T> axis_ = sva::Vector3<T>::UnitZ();
  sva::Vector3<T> u_ = sva::Vector3<T>::UnitX();
  sva::Vector3<T> w_ = sva::Vector3<T>::UnitY();
  int params_ = 0;
  int dof_ = 0;
  MotionSubspace S_;
};

using Joint = JointTpl<double>;

/// "Joint: name" (RBDyn's format).
template<typename T>
std::ostream & operator<<(std::ostream & out, const JointTpl<T> & j)
{
  return out << "Joint: " << j.name();
}

// ---------------------------------------------------------------------------------------------

template<typename T>
void JointTpl<T>::construct(const sva::Vector3<T> & axis)
{
  const bool needsAxis = type_ == Rev || type_ == Prism || type_ == Cylindrical || type_ == Planar;
  if(needsAxis)
  {
    const T n = axis.norm();
    if(!(n > T(0) && n < T(std::numeric_limits<double>::infinity()))) // also false for NaN
      throw std::domain_error("joint '" + name_ + "': axis must be finite and non-zero");
    axis_ = axis / n;
  }
  S_ = MotionSubspace::Zero(6, 0);
  switch(type_)
  {
    case Rev:
      params_ = dof_ = 1;
      S_ = MotionSubspace::Zero(6, 1);
      S_.template block<3, 1>(0, 0) = axis_;
      break;
    case Prism:
      params_ = dof_ = 1;
      S_ = MotionSubspace::Zero(6, 1);
      S_.template block<3, 1>(3, 0) = axis_;
      break;
    case Cylindrical:
      params_ = dof_ = 2;
      S_ = MotionSubspace::Zero(6, 2);
      S_.template block<3, 1>(0, 0) = axis_;
      S_.template block<3, 1>(3, 1) = axis_;
      break;
    case Planar:
    {
      // In-plane basis (u, w, n) right-handed: u from the world axis least aligned with n.
      using std::abs;
      int k = 0;
      for(int i = 1; i < 3; ++i)
        if(abs(axis_(i)) < abs(axis_(k)) - T(1e-12)) k = i;
      const sva::Vector3<T> e = sva::Vector3<T>::Unit(k);
      u_ = (e - e.dot(axis_) * axis_).normalized();
      w_ = axis_.cross(u_);
      params_ = dof_ = 3;
      S_ = MotionSubspace::Zero(6, 3);
      S_.template block<3, 1>(0, 0) = axis_;
      S_.template block<3, 1>(3, 1) = u_;
      S_.template block<3, 1>(3, 2) = w_;
      break;
    }
    case Spherical:
      params_ = 4;
      dof_ = 3;
      S_ = MotionSubspace::Zero(6, 3);
      S_.template block<3, 3>(0, 0).setIdentity();
      break;
    case Free:
      params_ = 7;
      dof_ = 6;
      S_ = MotionSubspace::Identity(6, 6);
      break;
    case Fixed:
      params_ = dof_ = 0;
      break;
  }
}

template<typename T>
sva::PTransform<T> JointTpl<T>::forwardPose(const std::vector<T> & q) const
{
  using Vec3 = sva::Vector3<T>;
  // Rotation of a quaternion stored [w x y z]; a non-unit quaternion stands for its normalisation.
  auto quatE = [](const T * p) {
    Eigen::Quaternion<T> quat(p[0], p[1], p[2], p[3]);
    quat.normalize();
    return sva::Matrix3<T>(quat.toRotationMatrix().transpose()); // E = R(quat)^T
  };
  auto axisE = [this](T angle) {
    return sva::Matrix3<T>(Eigen::AngleAxis<T>(-angle, axis_).toRotationMatrix()); // R(a,q)^T
  };
  switch(type_)
  {
    case Rev:
      return sva::PTransform<T>(axisE(q[0]));
    case Prism:
      return sva::PTransform<T>(Vec3(axis_ * q[0]));
    case Cylindrical:
      return sva::PTransform<T>(axisE(q[0]), Vec3(axis_ * q[1]));
    case Planar:
    {
      // RBDyn: PTransform(RotZ(q0), RotZ(q0)^T (q1, q2, 0)): (q1, q2) are the successor's origin in
      // successor axes, so r = R(n, q0) (q1 u + q2 w) in the predecessor frame
      const sva::Matrix3<T> E = axisE(q[0]);
      return sva::PTransform<T>(E, Vec3(E.transpose() * (u_ * q[1] + w_ * q[2])));
    }
    case Spherical:
      return sva::PTransform<T>(quatE(q.data()));
    case Free:
      return sva::PTransform<T>(quatE(q.data()), Vec3(q[4], q[5], q[6]));
    case Fixed:
    default:
      return sva::PTransform<T>::Identity();
  }
}

extern template class JointTpl<double>;
extern template class JointTpl<long double>;

} // namespace rbd
