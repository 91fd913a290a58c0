#pragma once
// Helpers of the kinematics_ext tests: random models in double or long double, tolerances per
// scalar, and a local q ⊕ dq (independent of rbd/EulerIntegration.h) for finite differences.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <rbd/FA.h>
#include <rbd/FK.h>
#include <rbd/FV.h>

#include "TestModels.h"

namespace kinext
{

/// Tolerances (~15x the largest error measured over the seeded cases): exact = two exact formulas;
/// solve = through forwardDynamics (cond(H) up to ~1e7 on these trees); fd = a central difference
/// with step h. (-DKINEXT_MEASURE sets them to ~0, to read the measured errors off the failures.)
template<typename T>
struct Prec;
#ifndef KINEXT_MEASURE
template<>
struct Prec<double>
{
  static constexpr double exact = 1e-13;
  static constexpr double solve = 1e-9;
  static constexpr double fd = 2e-8;
  static constexpr double h = 1e-6;
};
template<>
struct Prec<long double>
{
  static constexpr double exact = 1e-15;
  static constexpr double solve = 2e-13;
  static constexpr double fd = 1e-10;
  static constexpr double h = 1e-7;
};
#else
template<>
struct Prec<double>
{
  static constexpr double exact = 1e-40, solve = 1e-40, fd = 1e-40, h = 1e-6;
};
template<>
struct Prec<long double>
{
  static constexpr double exact = 1e-40, solve = 1e-40, fd = 1e-40, h = 1e-7;
};
#endif

using Scalars = ::testing::Types<double, long double>;

/// X with its rotation re-orthonormalised in T (a double rotation cast to long double is orthonormal
/// to 1e-16 only, and the algorithms take E^T for E^-1).
template<typename T>
sva::PTransform<T> orthonormalized(const sva::PTransform<T> & X)
{
  const Eigen::Quaternion<T> quat = Eigen::Quaternion<T>(X.rotation()).normalized();
  return sva::PTransform<T>(sva::Matrix3<T>(quat.toRotationMatrix()), X.translation());
}

/// Random tree of n bodies (every joint type) with the given root joint, cast to T with orthonormal
/// rotations. The tree is rooted at a random body, so that the joints between it and b0 are
/// backward ones (randomGraph's backwardProbability, asked for too, links child -> parent with
/// isB1toB2 = false, which is again a forward joint).
template<typename T>
rbd::MultiBodyTpl<T> randomModel(rbdtest::Rng & rng, int n, rbd::Joint::Type root)
{
  rbdtest::RandomTreeOptions opt;
  opt.backwardProbability = 0.3;
  const rbd::MultiBodyGraph mbg = rbdtest::randomGraph(rng, n, opt);
  const std::string rootBody = "b" + std::to_string(std::uniform_int_distribution<int>(0, n - 1)(rng));
  const auto mb = mbg.makeMultiBody(rootBody, root, rbdtest::randomTransform(rng)).template cast<T>();
  std::vector<sva::PTransform<T>> Xt;
  for(const auto & X : mb.transforms()) Xt.push_back(orthonormalized(X));
  return rbd::MultiBodyTpl<T>(mb.bodies(), mb.joints(), mb.predecessors(), mb.successors(), mb.parents(), Xt);
}

/// A root joint type drawn among Free, Fixed, Spherical, Planar and Rev.
inline rbd::Joint::Type randomRoot(rbdtest::Rng & rng)
{
  static const rbd::Joint::Type types[] = {rbd::Joint::Free, rbd::Joint::Fixed, rbd::Joint::Spherical,
                                           rbd::Joint::Planar, rbd::Joint::Rev};
  return types[std::uniform_int_distribution<int>(0, 4)(rng)];
}

/// q ⊕ dq on one joint. Rev/Prism/Cylindrical: q += dq. Spherical: quat ← quat ⊗ exp(dω).
/// Free: translation += R(quat) dv, then quat as Spherical. Planar ((x, y) in successor axes, RBDyn):
/// [x y] += [du dw] - dθ J [x y] (J = [0 -1; 1 0], the first-order step), θ += dθ.
template<typename T>
void perturbJoint(const rbd::JointTpl<T> & joint, std::vector<T> & q, const T * dq)
{
  auto rotate = [](std::vector<T> & qq, const sva::Vector3<T> & w) {
    const Eigen::Quaternion<T> quat(qq[0], qq[1], qq[2], qq[3]);
    const T th = w.norm();
    Eigen::Quaternion<T> e(T(1), T(0), T(0), T(0));
    if(th > T(0)) e = Eigen::Quaternion<T>(Eigen::AngleAxis<T>(th, w / th));
    const Eigen::Quaternion<T> r = quat * e;
    qq[0] = r.w();
    qq[1] = r.x();
    qq[2] = r.y();
    qq[3] = r.z();
  };
  switch(joint.type())
  {
    case rbd::Joint::Spherical:
      rotate(q, sva::Vector3<T>(dq[0], dq[1], dq[2]));
      break;
    case rbd::Joint::Free:
    {
      const Eigen::Quaternion<T> quat(q[0], q[1], q[2], q[3]);
      const sva::Vector3<T> dr = quat.toRotationMatrix() * sva::Vector3<T>(dq[3], dq[4], dq[5]);
      for(int k = 0; k < 3; ++k) q[static_cast<std::size_t>(4 + k)] += dr(k);
      rotate(q, sva::Vector3<T>(dq[0], dq[1], dq[2]));
      break;
    }
    case rbd::Joint::Planar:
    {
      const T x = q[1], y = q[2];
      q[1] += dq[1] + dq[0] * y;
      q[2] += dq[2] - dq[0] * x;
      q[0] += dq[0];
      break;
    }
    default:
      for(int k = 0; k < joint.dof(); ++k) q[static_cast<std::size_t>(k)] += dq[k];
  }
}

/// q ⊕ dq for the whole tree (dq flat, size nrDof).
template<typename T>
std::vector<std::vector<T>> perturb(const rbd::MultiBodyTpl<T> & mb, std::vector<std::vector<T>> q,
                                    const Eigen::Matrix<T, Eigen::Dynamic, 1> & dq)
{
  for(int i = 0; i < mb.nrJoints(); ++i)
    perturbJoint(mb.joint(i), q[static_cast<std::size_t>(i)], dq.data() + mb.jointPosInDof(i));
  return q;
}

/// Run FK and FV.
template<typename T>
void kin(const rbd::MultiBodyTpl<T> & mb, rbd::MultiBodyConfigTpl<T> & mbc)
{
  rbd::forwardKinematics(mb, mbc);
  rbd::forwardVelocity(mb, mbc);
}

/// A copy of mbc moved along the trajectory q(t) = q ⊕ (alpha t + alphaD t²/2), alpha(t) = alpha +
/// alphaD t, with FK and FV run (alphaD is a flat vector, possibly zero).
template<typename T>
rbd::MultiBodyConfigTpl<T> along(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc, T t,
                                 const Eigen::Matrix<T, Eigen::Dynamic, 1> & alphaD)
{
  rbd::MultiBodyConfigTpl<T> out = mbc;
  const Eigen::Matrix<T, Eigen::Dynamic, 1> alpha = rbd::dofToVector(mb, mbc.alpha);
  out.q = perturb(mb, mbc.q, Eigen::Matrix<T, Eigen::Dynamic, 1>(alpha * t + alphaD * (t * t / 2)));
  out.alpha = rbd::vectorToDof(mb, alpha + alphaD * t);
  kin(mb, out);
  return out;
}

/// Same with alphaD = 0 (q ⊕ alpha t, constant alpha).
template<typename T>
rbd::MultiBodyConfigTpl<T> along(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc, T t)
{
  return along(mb, mbc, t, Eigen::Matrix<T, Eigen::Dynamic, 1>(Eigen::Matrix<T, Eigen::Dynamic, 1>::Zero(mb.nrDof())));
}

/// A copy of mbc with alpha = e_k (flat unit vector), for column-wise finite differences.
template<typename T>
rbd::MultiBodyConfigTpl<T> withUnitAlpha(const rbd::MultiBodyTpl<T> & mb, const rbd::MultiBodyConfigTpl<T> & mbc,
                                         int k)
{
  rbd::MultiBodyConfigTpl<T> out = mbc;
  out.alpha = rbd::vectorToDof(mb, Eigen::Matrix<T, Eigen::Dynamic, 1>::Unit(mb.nrDof(), k));
  kin(mb, out);
  return out;
}

/// w from a skew-symmetric-ish matrix W (its skew part's axial vector).
template<typename T>
sva::Vector3<T> vee(const sva::Matrix3<T> & W)
{
  return sva::Vector3<T>(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1)) / T(2);
}

/// Rotation from body i to world coordinates (R = E_0_i^T).
template<typename T>
sva::Matrix3<T> R_0(const rbd::MultiBodyConfigTpl<T> & mbc, int i)
{
  return mbc.bodyPosW[static_cast<std::size_t>(i)].rotation().transpose();
}

} // namespace kinext
