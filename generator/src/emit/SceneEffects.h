#pragma once
// The effects of a scene as the emitter sees them (indices into the RobotModel), and the bodies of
// the functions a scene header adds to the plain API. Semantics: rbd/scene/Scene.h; for forward
// and inverse dynamics
//   (H + diag(armature)) alphaD = tau - damping.*alpha - friction.*alpha./sqrt(alpha.^2 + v_s^2)
//                                 + J_c^T f_contact + J_w^T wrenches - b(q, alpha),
// b = RNEA with alphaD = 0, the scene's gravity (or none), velocity terms when enabled.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "../codegen/Spatial.h"
#include "Functions.h"

namespace rbdgen::emit
{

struct SceneContact
{
  std::string name;
  int body = 0;                                   ///< index in rm.bodies
  Eigen::Vector3d point = Eigen::Vector3d::Zero(); ///< in the link frame
};

struct SceneEffects
{
  std::optional<Eigen::Vector3d> gravity;   ///< world, m/s^2; nullopt: no gravity
  bool velocityTerms = true;                ///< Coriolis and centrifugal terms
  std::vector<double> damping, friction, armature; ///< per dof (size nv)
  double frictionVelocity = 1e-2;           ///< v_s
  std::vector<int> wrenchBodies;            ///< indices in rm.bodies, in the order of the wrench inputs
  std::vector<SceneContact> contacts;
  double stiffness = 0, contactDamping = 0, mu = 0, slipVelocity = 1e-3, groundHeight = 0;

  bool anyNonZero(const std::vector<double> & v) const;
  bool hasDamping() const { return anyNonZero(damping); }
  bool hasFriction() const { return anyNonZero(friction); }
  bool hasArmature() const { return anyNonZero(armature); }
};

/// The contact point in its owner's body frame (constant).
cg::Vec3 contactPointInOwner(const RobotModel & rm, const SceneContact & c);
/// World force of the compliant contact model at world position p, velocity pd (names from h:
/// h_depth, h_push, h_fn, h_vt2 when mu != 0).
cg::Vec3 emitContactForce(cg::Block & b, const SceneEffects & fx, const cg::Vec3 & p, const cg::Vec3 & pd,
                          const std::string & h);
/// World position r + E^T p and velocity E^T (v + w x p) of body point p (X0 = (E, r), body velocity v).
void emitPointMotion(cg::Block & b, const cg::Xform & X0, const cg::Motion & v, const cg::Vec3 & p, cg::Vec3 & pos,
                     cg::Vec3 & vel, const std::string & h);

/// Scene inverse dynamics (withAlphaD) or the bias of forward dynamics (alphaD = 0): reads q, alpha
/// [, alphaD] [, wrenches]; fills `tau` with (H + diag(armature)) alphaD + b + damping + friction
/// - contact and wrench torques.
EmittedBody sceneRneaBody(const RobotModel & rm, const SceneEffects & fx, bool withAlphaD);

/// Reads q, alpha, alphaD [, wrenches]; fills the entries of d.dtau_dq, d.dtau_dalpha on the dof
/// tree's paths (dofs one the other or its ancestor) of the inverse dynamics with effects fx
/// (tangent convention of rbd/IDDerivatives.h; wrenches held constant; contact forces
/// differentiated where a point is pushed); the others are derivativeZerosOffPaths'.
EmittedBody inverseDynamicsDerivativesBody(const RobotModel & rm, const SceneEffects & fx);
/// The lines setting the entries of d.dtau_dq and d.dtau_dalpha off the dof tree's paths to zero,
/// as runs of rows per column.
std::string derivativeZerosOffPaths(const RobotModel & rm);
/// Reads q, alpha, tau [, wrenches]; fills d (FdDerivatives<S>: alphaD, dalphaD_dq, dalphaD_dalpha,
/// Minv) of the forward dynamics with effects fx, calling inverse_dynamics_derivatives(); biasCall:
/// the bias call (nonlinear_effects or generalized_bias; empty: none), wrenchArg ", wrenches" or "".
EmittedBody forwardDynamicsDerivativesBody(const RobotModel & rm, const SceneEffects & fx, const std::string & biasCall,
                                            const std::string & wrenchArg);

/// Reads q, alpha; fills `res[c]` (world force at contact c, 3-vector).
EmittedBody contactForcesBody(const RobotModel & rm, const SceneEffects & fx);

/// Reads q; returns the world pose of link `body` in `res` (Pose<S>).
EmittedBody linkPoseBody(const RobotModel & rm, int body);
/// Reads q; fills `J` (6 x nv, world axes at the origin of link `body`).
EmittedBody linkJacobianBody(const RobotModel & rm, int body);
/// Reads q; fills `com` (centre of mass, world coordinates).
EmittedBody centerOfMassQBody(const RobotModel & rm);
/// Reads q, alpha; fills `h` (centroidal momentum [angular about the CoM; linear], world axes).
EmittedBody centroidalMomentumBody(const RobotModel & rm);
/// Reads q, alpha; sets `e` to the kinetic energy alpha^T (H + diag(armature)) alpha / 2 (kinetic)
/// or to the potential energy of the scene's gravity -g . sum m_i c_i (not kinetic).
EmittedBody energyBody(const RobotModel & rm, const SceneEffects & fx, bool kinetic);

} // namespace rbdgen::emit
