#pragma once
// MultiBodyConfig: the state of a MultiBody and the results of the algorithms (plain struct).
// Per-joint vectors are indexed by joint, per-body vectors by body (joint i moves body i).

#include <stdexcept>
#include <string>
#include <vector>

#include <rbd/MultiBody.h>

namespace rbd
{

template<typename T>
struct MultiBodyConfigTpl
{
  using Scalar = T;
  using VectorX = Eigen::Matrix<T, Eigen::Dynamic, 1>;

  MultiBodyConfigTpl() = default;
  explicit MultiBodyConfigTpl(const MultiBodyTpl<T> & mb);

  /// Set q to the identity configuration and alpha, alphaD, jointTorque and force to zero.
  void zero(const MultiBodyTpl<T> & mb);

  // --- inputs, by joint ---
  std::vector<std::vector<T>> q;           ///< generalised position (Free: [qw qx qy qz x y z])
  std::vector<std::vector<T>> alpha;       ///< generalised velocity (Free: [w; v] in the body frame)
  std::vector<std::vector<T>> alphaD;      ///< generalised acceleration
  // --- inputs, by body ---
  std::vector<sva::ForceVec<T>> force;     ///< external force on each body, world coordinates at the world origin
  sva::Vector3<T> gravity{T(0), T(0), T(9.81)}; ///< gravity acceleration, opposite sign (RBDyn): +z means g along -z

  // --- by joint (filled by the algorithms) ---
  std::vector<sva::PTransform<T>> jointConfig;   ///< X_j(q): joint predecessor frame to successor frame (FK)
  std::vector<sva::MotionVec<T>> jointVelocity;  ///< S alpha (FV)
  std::vector<std::vector<T>> jointTorque;       ///< generalised force (ID output, FD input)
  std::vector<Eigen::Matrix<T, 6, Eigen::Dynamic>> motionSubspace; ///< S(q) per joint, successor frame (FK)

  // --- by body (filled by the algorithms) ---
  std::vector<sva::PTransform<T>> parentToSon; ///< X_p_i: parent body to body i (FK)
  std::vector<sva::PTransform<T>> bodyPosW;    ///< X_0_i: world to body i (FK)
  std::vector<sva::MotionVec<T>> bodyVelW;     ///< body i velocity at its origin, world-aligned axes (FV)
  std::vector<sva::MotionVec<T>> bodyVelB;     ///< body i velocity in body i coordinates (FV)
  std::vector<sva::MotionVec<T>> bodyAccB;     ///< body i acceleration in body i coordinates, no gravity (FA)
};

using MultiBodyConfig = MultiBodyConfigTpl<double>;

template<typename T>
MultiBodyConfigTpl<T>::MultiBodyConfigTpl(const MultiBodyTpl<T> & mb)
{
  const std::size_t n = static_cast<std::size_t>(mb.nrJoints());
  q.resize(n);
  alpha.resize(n);
  alphaD.resize(n);
  jointTorque.resize(n);
  motionSubspace.resize(n);
  for(std::size_t i = 0; i < n; ++i)
    motionSubspace[i] = mb.joint(static_cast<int>(i)).motionSubspace();
  force.assign(n, sva::ForceVec<T>::Zero());
  jointConfig.assign(n, sva::PTransform<T>::Identity());
  jointVelocity.assign(n, sva::MotionVec<T>::Zero());
  parentToSon.assign(n, sva::PTransform<T>::Identity());
  bodyPosW.assign(n, sva::PTransform<T>::Identity());
  bodyVelW.assign(n, sva::MotionVec<T>::Zero());
  bodyVelB.assign(n, sva::MotionVec<T>::Zero());
  bodyAccB.assign(n, sva::MotionVec<T>::Zero());
  zero(mb);
}

template<typename T>
void MultiBodyConfigTpl<T>::zero(const MultiBodyTpl<T> & mb)
{
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    q[k] = mb.joint(i).zeroParam();
    alpha[k] = mb.joint(i).zeroDof();
    alphaD[k] = mb.joint(i).zeroDof();
    jointTorque[k] = mb.joint(i).zeroDof();
    force[k] = sva::ForceVec<T>::Zero();
  }
}

// --- flat vectors <-> per-joint vectors ------------------------------------------------------
// The scalar is deduced from the per-joint vectors only, so that an Eigen::VectorXd, a segment or
// any expression converts to the Eigen::Ref parameter (a Ref<VectorX<T>> cannot deduce T).

template<typename T>
using FlatVectorRef = Eigen::Ref<Eigen::Matrix<sva::detail::identity_t<T>, Eigen::Dynamic, 1>>;
template<typename T>
using ConstFlatVectorRef = Eigen::Ref<const Eigen::Matrix<sva::detail::identity_t<T>, Eigen::Dynamic, 1>>;

/// Concatenate per-joint values (q, or alpha-like) into e (whose size must match).
template<typename T>
void paramToVector(const std::vector<std::vector<T>> & v, FlatVectorRef<T> e)
{
  Eigen::Index pos = 0;
  for(const auto & joint : v)
    for(const T & x : joint) e(pos++) = x;
}

/// Split e into per-joint values, using the sizes already in v.
template<typename T>
void vectorToParam(const ConstFlatVectorRef<T> & e, std::vector<std::vector<T>> & v)
{
  Eigen::Index pos = 0;
  for(auto & joint : v)
    for(T & x : joint) x = e(pos++);
}

/// Same as paramToVector / vectorToParam (RBDyn's names for alpha-like values).
template<typename T>
void dofToVector(const std::vector<std::vector<T>> & v, FlatVectorRef<T> e)
{
  paramToVector<T>(v, e);
}
template<typename T>
void vectorToDof(const ConstFlatVectorRef<T> & e, std::vector<std::vector<T>> & v)
{
  vectorToParam<T>(e, v);
}

/// Flat q vector of a configuration (size mb.nrParams()).
template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, 1> paramToVector(const MultiBodyTpl<T> & mb, const std::vector<std::vector<T>> & v)
{
  Eigen::Matrix<T, Eigen::Dynamic, 1> e(mb.nrParams());
  paramToVector<T>(v, e);
  return e;
}

/// Flat alpha-like vector (size mb.nrDof()).
template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, 1> dofToVector(const MultiBodyTpl<T> & mb, const std::vector<std::vector<T>> & v)
{
  Eigen::Matrix<T, Eigen::Dynamic, 1> e(mb.nrDof());
  paramToVector<T>(v, e);
  return e;
}

namespace detail
{
/// Per-joint vectors sized by params() (q-like) or dof() (alpha-like).
template<typename T>
std::vector<std::vector<T>> perJoint(const MultiBodyTpl<T> & mb, bool params)
{
  std::vector<std::vector<T>> v;
  for(const auto & j : mb.joints()) v.emplace_back(static_cast<std::size_t>(params ? j.params() : j.dof()));
  return v;
}
/// Throw std::out_of_range (RBDyn's type for these conversions) unless have == want.
inline void checkFlatSize(Eigen::Index have, Eigen::Index want, const char * what)
{
  if(have != want)
    throw std::out_of_range(std::string(what) + " size mismatch: expected " + std::to_string(want) + ", got " +
                            std::to_string(have));
}
template<typename T>
Eigen::Index totalSize(const std::vector<std::vector<T>> & v)
{
  Eigen::Index n = 0;
  for(const auto & joint : v) n += static_cast<Eigen::Index>(joint.size());
  return n;
}
/// Throw std::out_of_range unless v has one vector per joint of params() (or dof()) values.
template<typename T>
void checkPerJoint(const MultiBodyTpl<T> & mb, const std::vector<std::vector<T>> & v, bool params)
{
  checkFlatSize(static_cast<Eigen::Index>(v.size()), mb.nrJoints(), "joint vector");
  for(int i = 0; i < mb.nrJoints(); ++i)
    checkFlatSize(static_cast<Eigen::Index>(v[static_cast<std::size_t>(i)].size()),
                  params ? mb.joint(i).params() : mb.joint(i).dof(), params ? "joint parameters" : "joint dof");
}
} // namespace detail

/// Per-joint q from a flat vector (size mb.nrParams()).
template<typename T, typename Derived>
std::vector<std::vector<T>> vectorToParam(const MultiBodyTpl<T> & mb, const Eigen::MatrixBase<Derived> & e)
{
  std::vector<std::vector<T>> v = detail::perJoint(mb, true);
  vectorToParam<T>(e, v);
  return v;
}

/// Per-joint alpha-like values from a flat vector (size mb.nrDof()).
template<typename T, typename Derived>
std::vector<std::vector<T>> vectorToDof(const MultiBodyTpl<T> & mb, const Eigen::MatrixBase<Derived> & e)
{
  std::vector<std::vector<T>> v = detail::perJoint(mb, false);
  vectorToParam<T>(e, v);
  return v;
}

// Checked variants: throw std::out_of_range on a size mismatch (as RBDyn).
template<typename T>
void sParamToVector(const std::vector<std::vector<T>> & v, FlatVectorRef<T> e)
{
  detail::checkFlatSize(e.size(), detail::totalSize(v), "parameter vector");
  paramToVector<T>(v, e);
}
template<typename T>
void sVectorToParam(const ConstFlatVectorRef<T> & e, std::vector<std::vector<T>> & v)
{
  detail::checkFlatSize(e.size(), detail::totalSize(v), "parameter vector");
  vectorToParam<T>(e, v);
}
template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, 1> sParamToVector(const MultiBodyTpl<T> & mb, const std::vector<std::vector<T>> & v)
{
  detail::checkPerJoint(mb, v, true);
  return paramToVector(mb, v);
}
template<typename T>
Eigen::Matrix<T, Eigen::Dynamic, 1> sDofToVector(const MultiBodyTpl<T> & mb, const std::vector<std::vector<T>> & v)
{
  detail::checkPerJoint(mb, v, false);
  return dofToVector(mb, v);
}
template<typename T, typename Derived>
std::vector<std::vector<T>> sVectorToParam(const MultiBodyTpl<T> & mb, const Eigen::MatrixBase<Derived> & e)
{
  detail::checkFlatSize(e.size(), mb.nrParams(), "parameter vector");
  return vectorToParam(mb, e);
}
template<typename T, typename Derived>
std::vector<std::vector<T>> sVectorToDof(const MultiBodyTpl<T> & mb, const Eigen::MatrixBase<Derived> & e)
{
  detail::checkFlatSize(e.size(), mb.nrDof(), "dof vector");
  return vectorToDof(mb, e);
}

extern template struct MultiBodyConfigTpl<double>;
extern template struct MultiBodyConfigTpl<long double>;

} // namespace rbd
