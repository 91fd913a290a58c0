#pragma once
// Helpers of the loader tests: hand-written rotations, a mass matrix built from forwardVelocity
// alone, and the mapping of a floating-base state between two choices of base link.

#include <cmath>
#include <map>
#include <string>

#include <rbd/ConfigConverter.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/parsers/urdf.h>

namespace loadertest
{

/// Usual right-handed elementary rotations, written out (not from sva or Eigen).
inline Eigen::Matrix3d rotX(double a)
{
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  return m;
}
inline Eigen::Matrix3d rotY(double a)
{
  Eigen::Matrix3d m;
  m << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
  return m;
}
inline Eigen::Matrix3d rotZ(double a)
{
  Eigen::Matrix3d m;
  m << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return m;
}
/// URDF rpy: fixed-axis roll about x, then pitch about y, then yaw about z.
inline Eigen::Matrix3d rpy(double r, double p, double y) { return rotZ(y) * rotY(p) * rotX(r); }
/// Rodrigues: rotation by t about the unit axis a.
inline Eigen::Matrix3d axisAngle(const Eigen::Vector3d & a, double t)
{
  Eigen::Matrix3d K;
  K << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return Eigen::Matrix3d::Identity() + std::sin(t) * K + (1 - std::cos(t)) * K * K;
}

/// X_0_link: pose of the URDF link frame (not the body frame) of body i.
inline sva::PTransformd linkPose(const rbd::parsers::ParserResult & r, const rbd::MultiBodyConfig & mbc, int i)
{
  return r.bodyBaseTransforms.at(r.mb.body(i).name()).inv() * mbc.bodyPosW[static_cast<std::size_t>(i)];
}

/// Joint-space mass matrix from forwardVelocity only: body Jacobians J_i (columns = body
/// velocities for unit alphas), M = sum_i J_i^T I_i J_i. mbc must hold FK at the wanted q.
inline Eigen::MatrixXd massMatrixFromVelocities(const rbd::MultiBody & mb, rbd::MultiBodyConfig mbc)
{
  const int n = mb.nrDof();
  std::vector<Eigen::Matrix<double, 6, Eigen::Dynamic>> J(static_cast<std::size_t>(mb.nrBodies()),
                                                          Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, n));
  for(int k = 0; k < n; ++k)
  {
    mbc.alpha = rbd::vectorToDof(mb, Eigen::VectorXd(Eigen::VectorXd::Unit(n, k)));
    rbd::forwardVelocity(mb, mbc);
    for(std::size_t i = 0; i < J.size(); ++i) J[i].col(k) = mbc.bodyVelB[i].vector();
  }
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  for(int i = 0; i < mb.nrBodies(); ++i)
    M += J[static_cast<std::size_t>(i)].transpose() * mb.body(i).inertia().matrix() * J[static_cast<std::size_t>(i)];
  return M;
}

/// Kinetic energy sum_i 1/2 v_i . I_i v_i (mbc after FK and FV).
inline double kineticEnergy(const rbd::MultiBody & mb, const rbd::MultiBodyConfig & mbc)
{
  double e = 0;
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto & v = mbc.bodyVelB[static_cast<std::size_t>(i)];
    e += 0.5 * (mb.body(i).inertia() * v).dot(v);
  }
  return e;
}

/// State of the floating-base model `to` (its Free root on another link) giving every link the
/// pose and velocity it has in `from` (FK and FV done): non-root joints copied by name, root
/// joint set from the world pose and velocity of `to`'s base link in `from`.
inline void mapFloatingState(const rbd::parsers::ParserResult & from, const rbd::MultiBodyConfig & mbcFrom,
                             const rbd::parsers::ParserResult & to, rbd::MultiBodyConfig & mbcTo)
{
  rbd::ConfigConverter(from.mb, to.mb).convert(mbcFrom, mbcTo);
  const std::string base = to.mb.body(0).name();
  const int iFrom = from.mb.bodyIndexByName(base);
  // Base body frame in `to` relative to its body frame in `from`: X_bodyFrom_bodyTo.
  const sva::PTransformd X_from_to = to.bodyBaseTransforms.at(base) * from.bodyBaseTransforms.at(base).inv();
  const sva::PTransformd X_0_base = X_from_to * mbcFrom.bodyPosW[static_cast<std::size_t>(iFrom)];
  // Free joint: X_j = (R(quat)^T, r) = X_0_base.
  const Eigen::Quaterniond quat(Eigen::Matrix3d(X_0_base.rotation().transpose()));
  const Eigen::Vector3d r = X_0_base.translation();
  mbcTo.q[0] = {quat.w(), quat.x(), quat.y(), quat.z(), r.x(), r.y(), r.z()};
  const sva::MotionVecd v = X_from_to * mbcFrom.bodyVelB[static_cast<std::size_t>(iFrom)];
  mbcTo.alpha[0] = {v.angular().x(), v.angular().y(), v.angular().z(), v.linear().x(), v.linear().y(), v.linear().z()};
}

} // namespace loadertest
