#pragma once
// A scene: which effects a simulation or a controller needs, read from a small XML file
// (docs/SCENES.md is the format's reference). The generator emits only these effects; the
// runtime evaluates the same scene generically (rbd/scene/SceneDynamics.h), as the reference.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rbd::scene
{

/// Per-joint effects (applied to every dof of the joint).
struct JointEffects
{
  double damping = 0.0;   ///< viscous, N m s/rad (N s/m): tau -= damping * alpha
  double friction = 0.0;  ///< Coulomb, N m (N): tau -= friction * alpha / sqrt(alpha^2 + v_s^2)
  double armature = 0.0;  ///< rotor inertia reflected to the joint, kg m^2 (kg): H_ii += armature
};

/// A contact point on a body against the ground plane z = groundHeight (normal +z, world).
struct ContactPoint
{
  std::string name;
  std::string body;                        ///< URDF link name
  Eigen::Vector3d point = Eigen::Vector3d::Zero(); ///< in the link frame
};

/// Compliant contact: penetration d = groundHeight - p_z, normal speed vn = pdot_z,
///   fn = max(0, stiffness d - damping vn) when d > 0, else 0;
///   tangential velocity vt = (pdot_x, pdot_y): ft = -mu fn vt / sqrt(|vt|^2 + slipVelocity^2).
struct ContactModel
{
  double stiffness = 0.0;     ///< N/m
  double damping = 0.0;       ///< N s/m
  double mu = 0.0;            ///< friction coefficient
  double slipVelocity = 1e-3; ///< m/s, regularisation of Coulomb friction
  double groundHeight = 0.0;  ///< m
};

enum class Integrator
{
  SemiImplicitEuler, ///< alpha+ = alpha + dt a(q, alpha); q+ = integrate(q, alpha+ dt) (exact exponential)
  ExplicitEuler,     ///< q+ = integrate(q, alpha dt); alpha+ = alpha + dt a(q, alpha)
  RK4                ///< classical RK4 on (q, alpha) with qdot = configurationDerivative(q, alpha);
                     ///< quaternions renormalised after the step
};

/// Requested outputs (the generated header gets a function for each).
struct Outputs
{
  std::vector<std::string> poses;     ///< link names: world pose
  std::vector<std::string> jacobians; ///< link names: 6 x nv Jacobian (world axes, link origin)
  bool com = false;                   ///< centre of mass (world)
  bool momentum = false;              ///< centroidal momentum [angular about CoM; linear]
  bool energy = false;                ///< kinetic + potential energy
  bool derivatives = false;           ///< inverse/forward dynamics derivatives (contacts included)
  bool kinematics = false;            ///< forward_kinematics of every link, jacobian(body, q), center_of_mass
};

/// Simple controller used by `rbdgen simulate` (the generated step() takes tau from the caller).
struct Controller
{
  /// PdGravity (added): PD hold plus the scene's gravity torques g(q) (gravity compensation).
  enum class Type { ZeroTorque, PdHold, PdGravity } type = Type::ZeroTorque;
  double kp = 0.0, kd = 0.0;          ///< PD hold: tau = kp (q_target - q) - kd alpha on 1-dof joints
  std::map<std::string, double> target; ///< joint name -> target position (default: initial q)
};

struct Scene
{
  std::string file;                 ///< path of the scene file (for messages)
  std::string name;
  // robot
  std::string urdf;                 ///< resolved path (relative paths are relative to the scene file)
  bool floatingBase = false;
  std::string baseLink;             ///< empty: the URDF root
  // effects
  std::optional<Eigen::Vector3d> gravity = Eigen::Vector3d(0, 0, -9.81); ///< world, m/s^2; nullopt: none
  bool velocityTerms = true;        ///< Coriolis and centrifugal terms
  double frictionVelocity = 1e-2;   ///< v_s of the Coulomb friction regularisation (rad/s or m/s)
  std::map<std::string, JointEffects> joints; ///< joint name -> damping/friction/armature (URDF + overrides)
  std::map<std::string, std::vector<double>> locked; ///< joint name -> held position (its q entries)
  std::vector<std::string> externalWrenches;  ///< link names receiving a caller-supplied wrench
  std::vector<ContactPoint> contacts;
  ContactModel contactModel;
  Outputs outputs;
  // simulation
  Integrator integrator = Integrator::SemiImplicitEuler;
  double dt = 1e-3;                 ///< s
  double duration = 1.0;            ///< s (default of `rbdgen simulate`)
  std::map<std::string, std::vector<double>> initialQ;     ///< joint name -> q entries (default: zero / identity)
  std::map<std::string, std::vector<double>> initialAlpha; ///< joint name -> alpha entries (default: zero)
  Controller controller;
};

} // namespace rbd::scene
