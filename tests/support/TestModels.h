#pragma once
// Test models: random valid inertias, random trees with every joint type, random states.

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <rbd/MultiBodyConfig.h>
#include <rbd/MultiBodyGraph.h>

namespace rbdtest
{

using Rng = std::mt19937;

inline double uniform(Rng & rng, double lo, double hi)
{
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Every draw below is its own statement: function arguments are evaluated in an unspecified order
// (g++ and clang++ differ), and the same seed must give the same model with either compiler.

/// N numbers uniform in [lo, hi], drawn in index order.
template<int N>
Eigen::Matrix<double, N, 1> uniformVec(Rng & rng, double lo, double hi)
{
  Eigen::Matrix<double, N, 1> v;
  for(int i = 0; i < N; ++i) v[i] = uniform(rng, lo, hi);
  return v;
}

inline Eigen::Vector3d randomUnit(Rng & rng)
{
  Eigen::Vector3d v;
  do
  {
    v = uniformVec<3>(rng, -1, 1);
  } while(v.norm() < 0.1);
  return v.normalized();
}

/// A random unit quaternion (w, x, y, z drawn in that order).
inline Eigen::Quaterniond randomQuaternion(Rng & rng)
{
  const Eigen::Vector4d wxyz = uniformVec<4>(rng, -1, 1);
  return Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]).normalized();
}

inline Eigen::Matrix3d randomRotation(Rng & rng)
{
  return randomQuaternion(rng).toRotationMatrix();
}

inline sva::PTransformd randomTransform(Rng & rng, double maxOffset = 0.5)
{
  const Eigen::Matrix3d E = randomRotation(rng);
  return sva::PTransformd(E, uniformVec<3>(rng, -maxOffset, maxOffset));
}

/// A physically valid spatial inertia at the body origin: principal moments satisfying the
/// triangle inequality, rotated, with an offset centre of mass.
inline sva::RBInertiad randomInertia(Rng & rng, double massLo = 0.2, double massHi = 3.0)
{
  const double m = uniform(rng, massLo, massHi);
  const Eigen::Vector3d p = uniformVec<3>(rng, 0.01, 0.1);
  // moments of a box with half-sizes p: I_x = m/3 (p_y^2 + p_z^2)...
  Eigen::Vector3d d(m / 3 * (p.y() * p.y() + p.z() * p.z()), m / 3 * (p.x() * p.x() + p.z() * p.z()),
                    m / 3 * (p.x() * p.x() + p.y() * p.y()));
  const Eigen::Matrix3d R = randomRotation(rng);
  const Eigen::Matrix3d Ic = R * d.asDiagonal() * R.transpose();
  const Eigen::Vector3d c = uniformVec<3>(rng, -0.2, 0.2);
  return sva::RBInertiad(m, m * c, sva::inertiaToOrigin(Ic, m, c, Eigen::Matrix3d::Identity()));
}

struct RandomTreeOptions
{
  std::vector<rbd::Joint::Type> types{rbd::Joint::Rev,         rbd::Joint::Prism, rbd::Joint::Spherical,
                                      rbd::Joint::Planar,      rbd::Joint::Cylindrical, rbd::Joint::Free,
                                      rbd::Joint::Fixed};
  double backwardProbability = 0.0; ///< chance that a joint is linked child -> parent
  double chainProbability = 0.5;    ///< chance that a new body hangs from the last one (vs any)
};

/// A random tree of n bodies "b0".."b{n-1}" linked by joints "j1".."j{n-1}" (b0 is the root).
inline rbd::MultiBodyGraph randomGraph(Rng & rng, int n, const RandomTreeOptions & opt = {})
{
  rbd::MultiBodyGraph mbg;
  for(int i = 0; i < n; ++i) mbg.addBody(rbd::Body(randomInertia(rng), "b" + std::to_string(i)));
  for(int i = 1; i < n; ++i)
  {
    const auto type = opt.types[std::uniform_int_distribution<std::size_t>(0, opt.types.size() - 1)(rng)];
    const std::string jn = "j" + std::to_string(i);
    Eigen::Vector3d axis = randomUnit(rng);
    if(uniform(rng, 0, 1) < 0.5) axis = Eigen::Vector3d::Unit(std::uniform_int_distribution<int>(0, 2)(rng));
    mbg.addJoint(rbd::Joint(type, axis, true, jn));
    const int parent = uniform(rng, 0, 1) < opt.chainProbability ? i - 1
                                                                 : std::uniform_int_distribution<int>(0, i - 1)(rng);
    const std::string pn = "b" + std::to_string(parent), cn = "b" + std::to_string(i);
    // A backward joint moves the parent w.r.t. the child (isB1toB2 = false with b1 = parent), so
    // the tree rooted at b0 traverses it against its direction.
    const bool backward = uniform(rng, 0, 1) < opt.backwardProbability;
    const sva::PTransformd X_p_j = randomTransform(rng), X_c_j = randomTransform(rng);
    mbg.linkBodies(pn, X_p_j, cn, X_c_j, jn, !backward);
  }
  return mbg;
}

/// Random q (unit quaternions), alpha, alphaD and jointTorque; no external force.
template<typename T = double>
void randomState(Rng & rng, const rbd::MultiBodyTpl<T> & mb, rbd::MultiBodyConfigTpl<T> & mbc, double qRange = 3.0,
                 double vRange = 2.0)
{
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    for(auto & x : mbc.q[k]) x = T(uniform(rng, -qRange, qRange));
    const auto t = mb.joint(i).type();
    if(t == rbd::Joint::Spherical || t == rbd::Joint::Free)
    {
      const Eigen::Quaterniond quat = randomQuaternion(rng);
      mbc.q[k][0] = T(quat.w());
      mbc.q[k][1] = T(quat.x());
      mbc.q[k][2] = T(quat.y());
      mbc.q[k][3] = T(quat.z());
    }
    for(auto & x : mbc.alpha[k]) x = T(uniform(rng, -vRange, vRange));
    for(auto & x : mbc.alphaD[k]) x = T(uniform(rng, -vRange, vRange));
    for(auto & x : mbc.jointTorque[k]) x = T(uniform(rng, -vRange, vRange));
  }
}

/// Copy the inputs (q, alpha, alphaD, jointTorque, force, gravity) into another scalar type.
template<typename U, typename T>
rbd::MultiBodyConfigTpl<U> castInputs(const rbd::MultiBodyTpl<U> & mbU, const rbd::MultiBodyConfigTpl<T> & mbc)
{
  rbd::MultiBodyConfigTpl<U> out(mbU);
  auto conv = [](const std::vector<std::vector<T>> & v) {
    std::vector<std::vector<U>> r(v.size());
    for(std::size_t i = 0; i < v.size(); ++i)
      for(const T & x : v[i]) r[i].push_back(U(x));
    return r;
  };
  out.q = conv(mbc.q);
  out.alpha = conv(mbc.alpha);
  out.alphaD = conv(mbc.alphaD);
  out.jointTorque = conv(mbc.jointTorque);
  for(std::size_t i = 0; i < mbc.force.size(); ++i) out.force[i] = mbc.force[i].template cast<U>();
  out.gravity = mbc.gravity.template cast<U>();
  return out;
}

/// Max |a - b| / max(1, |b|) over all entries.
template<typename A, typename B>
double relErr(const Eigen::MatrixBase<A> & a, const Eigen::MatrixBase<B> & b)
{
  if(b.size() == 0) return a.size() == 0 ? 0.0 : std::numeric_limits<double>::infinity();
  const double scale = std::max(1.0, static_cast<double>(b.template cast<double>().cwiseAbs().maxCoeff()));
  return static_cast<double>((a.template cast<double>() - b.template cast<double>()).cwiseAbs().maxCoeff()) / scale;
}

} // namespace rbdtest

/// EXPECT that two Eigen expressions agree to tol (max abs difference relative to max(1, |b|)).
#define EXPECT_MAT_NEAR(a, b, tol) EXPECT_LE(::rbdtest::relErr((a), (b)), (tol)) << "a=\n" << (a) << "\nb=\n" << (b)
