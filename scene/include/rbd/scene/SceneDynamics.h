#pragma once
// Generic (runtime) evaluation of a scene: the reference the scene-specialised generated code must
// match. Built from a SceneRobot and its Scene, with the MultiBody cast to the scalar T.
//
// Equations of motion of a scene (nv velocity coordinates, A = diag(armature)):
//   (H(q) + A) alphaD = tau - D alpha - f_c(alpha) - b(q, alpha) + J_c^T F_c + J_w^T W
//   D = diag(damping), f_c = friction .* alpha ./ sqrt(alpha.^2 + v_s^2)  (v_s = frictionVelocity)
//   b = RNEA(q, alpha, alphaD = 0) with the scene's gravity (none: zero) and, when velocityTerms is
//       off, alpha = 0 inside b (b = g(q)); the contact forces F_c always use the true velocities.
//   J_c^T F_c + J_w^T W: the contact forces (world, at each contact point) and the caller's external
//       wrenches (world coordinates at the world origin, one per scene external_wrench body) mapped
//       to the joints, computed by RNEA as mbc.force.
//
// Links vs bodies: the functions taking a link name (pose, jacobian) refer to the URDF link frame,
// which differs from the MultiBody body frame for the bodies moved by locked or backward joints
// (SceneRobot::robot.bodyBaseTransforms).
//
// Every function evaluates from scratch (no cached state): calls are independent and reentrant.

#include <string>
#include <vector>

#include <Eigen/Core>

#include <rbd/MultiBody.h>
#include <rbd/MultiBodyConfig.h>

#include "SceneLoader.h"

namespace rbd::scene
{

template<class T>
class SceneDynamicsTpl
{
public:
  using Scalar = T;
  using VectorX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector3 = Eigen::Matrix<T, 3, 1>;
  using Matrix3 = Eigen::Matrix<T, 3, 3>;
  using Wrenches = std::vector<sva::ForceVec<T>>;

  SceneDynamicsTpl(const SceneRobot & robot, const Scene & scene);

  const Scene & scene() const { return scene_; }
  const MultiBodyTpl<T> & mb() const { return mb_; }
  int nq() const { return mb_.nrParams(); }
  int nv() const { return mb_.nrDof(); }
  /// Per velocity coordinate (size nv).
  const VectorX & damping() const { return damping_; }
  const VectorX & friction() const { return friction_; }
  const VectorX & armature() const { return armature_; }
  /// Gravity acceleration in world coordinates (zero when the scene has none).
  const Vector3 & gravity() const { return gravityW_; }
  T totalMass() const { return totalMass_; }
  /// Index in mb() of the body carrying the URDF link (throws SceneError-free std::out_of_range).
  int bodyIndex(const std::string & link) const { return mb_.bodyIndexByName(link); }
  /// X_link_body: from the URDF link frame to the MultiBody body frame of that link.
  sva::PTransform<T> linkToBody(const std::string & link) const;

  /// alphaD from the equation above. wrenches: empty (all zero) or one per scene external wrench.
  VectorX forwardDynamics(const VectorX & q, const VectorX & alpha, const VectorX & tau,
                          const Wrenches & wrenches = {}) const;
  /// tau such that forwardDynamics(q, alpha, tau, wrenches) = alphaD.
  VectorX inverseDynamics(const VectorX & q, const VectorX & alpha, const VectorX & alphaD,
                          const Wrenches & wrenches = {}) const;
  /// H(q) + diag(armature).
  MatrixX massMatrix(const VectorX & q) const;
  /// g(q): the scene's gravity torques (RNEA at alpha = 0, alphaD = 0, no contact or external force).
  VectorX gravityTorques(const VectorX & q) const;
  /// Every term but the inertial one: tau - (H + A) alphaD for the true motion, i.e.
  /// b + D alpha + f_c - J_c^T F_c - J_w^T W.
  VectorX generalizedBias(const VectorX & q, const VectorX & alpha, const Wrenches & wrenches = {}) const;

  /// Derivatives of inverseDynamics (tangent convention of rbd/IDDerivatives.h; wrenches held
  /// constant; contact forces differentiated where a point is pushed, F = 0 elsewhere: at the
  /// contact boundary the one-sided derivative of the side the state is on), nv x nv each.
  struct IdDerivatives
  {
    MatrixX dtauDq, dtauDalpha;
  };
  IdDerivatives inverseDynamicsDerivatives(const VectorX & q, const VectorX & alpha, const VectorX & alphaD,
                                           const Wrenches & wrenches = {}) const;
  /// forwardDynamics and its derivatives: d alphaD = -(H + A)^-1 d ID at alphaD, d alphaD/d tau = (H + A)^-1.
  struct FdDerivatives
  {
    VectorX alphaD;
    MatrixX dalphaDDq, dalphaDDalpha, Minv;
  };
  FdDerivatives forwardDynamicsDerivatives(const VectorX & q, const VectorX & alpha, const VectorX & tau,
                                           const Wrenches & wrenches = {}) const;

  /// World position / velocity of each contact point (scene order).
  std::vector<Vector3> contactPositions(const VectorX & q) const;
  std::vector<Vector3> contactVelocities(const VectorX & q, const VectorX & alpha) const;
  /// World force on each contact point (Scene.h ContactModel), scene order.
  std::vector<Vector3> contactForces(const VectorX & q, const VectorX & alpha) const;

  /// 1/2 alpha^T (H + A) alpha.
  T kineticEnergy(const VectorX & q, const VectorX & alpha) const;
  /// -sum_i m_i g . c_i (zero without gravity).
  T potentialEnergy(const VectorX & q) const;
  /// sum over penetrating points of 1/2 stiffness d^2.
  T contactEnergy(const VectorX & q) const;

  /// X_0_link: world to URDF link frame.
  sva::PTransform<T> pose(const VectorX & q, const std::string & link) const;
  /// 6 x nv, world-aligned axes, at the link origin: J alpha = [w; v_origin] (world coordinates).
  MatrixX jacobian(const VectorX & q, const std::string & link) const;
  /// Centre of mass, world coordinates.
  Vector3 centerOfMass(const VectorX & q) const;
  /// [angular momentum about the CoM; linear momentum], world axes.
  sva::ForceVec<T> centroidalMomentum(const VectorX & q, const VectorX & alpha) const;

  /// mbc with q, alpha set and forwardKinematics + forwardVelocity done (checks the sizes).
  MultiBodyConfigTpl<T> kinematics(const VectorX & q, const VectorX & alpha) const;

private:
  /// RNEA bias with alphaD = 0 on mbc (FK/FV done), gravity of the scene, external forces force.
  VectorX rneaBias(MultiBodyConfigTpl<T> & mbc, const std::vector<sva::ForceVec<T>> & force) const;
  /// Body forces (world, world origin): contact forces at their points (if contacts) + the caller's wrenches.
  std::vector<sva::ForceVec<T>> bodyForces(const MultiBodyConfigTpl<T> & mbc, const Wrenches & wrenches,
                                           bool contacts = true) const;
  /// out -= the derivatives of J_c^T F_c (mbc: FK and FV at the true alpha).
  void subtractContactDerivatives(const MultiBodyConfigTpl<T> & mbc, const VectorX & alpha, IdDerivatives & out) const;
  std::vector<Vector3> contactPositions(const MultiBodyConfigTpl<T> & mbc) const;
  std::vector<Vector3> contactVelocities(const MultiBodyConfigTpl<T> & mbc) const;
  std::vector<Vector3> contactForces(const MultiBodyConfigTpl<T> & mbc) const;
  MatrixX massMatrix(const MultiBodyConfigTpl<T> & mbc) const;

  Scene scene_;
  MultiBodyTpl<T> mb_;
  std::vector<std::pair<std::string, sva::PTransform<T>>> linkToBody_;
  VectorX damping_, friction_, armature_;
  Vector3 gravityW_;
  T totalMass_ = T(0);
  std::vector<int> contactBodies_, wrenchBodies_;
  std::vector<Vector3> contactPointsB_; ///< contact points in their body's frame
};

using SceneDynamics = SceneDynamicsTpl<double>;

extern template class SceneDynamicsTpl<double>;
extern template class SceneDynamicsTpl<long double>;

} // namespace rbd::scene
