#pragma once
// Bodies of the emitted functions. Each returns the statements of one function body (indented),
// written from the robot model with every recursion unrolled.

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "../codegen/Expr.h"
#include "../model/RobotModel.h"
#include "../passes/JointKernels.h"

namespace rbdgen::emit
{

/// Floating-point operation counts of an emitted body (after dead-code removal at emission).
struct OpCount
{
  long mults = 0, adds = 0, calls = 0;
};

struct EmittedBody
{
  std::string text;
  OpCount ops;
};

/// The text (indented, unused locals removed) and operation counts of a finished body.
EmittedBody finish(const cg::Block & b);

/// Reads q; fills `res[b]` (std::array<Pose<S>, nbodies>) with every link's world pose.
EmittedBody forwardKinematicsBody(const RobotModel & rm);
/// detail::link_poses(X0s, res): every link's world pose from the shared joint poses (the header's
/// shared passes must be current, and have emitted joint_poses).
std::string linkPosesDefinition(const RobotModel & rm);
/// Reads q; declares the shared passes' K and X0s, fills `kin.frame[k]` (moving joints' body frames)
/// when `frames`, and calls detail::link_poses into `dst` (forward_kinematics: "res"; kinematics: "kin.pose").
EmittedBody linkPosesCallBody(const RobotModel & rm, const std::string & dst, bool frames);

/// Which terms of the recursive Newton-Euler algorithm are present.
struct RneaTerms
{
  bool velocity = true;      ///< alpha (Coriolis, centrifugal)
  bool acceleration = true;  ///< alphaD
  bool gravity = true;
  Eigen::Vector3d gravityVector = Eigen::Vector3d(0, 0, -9.81); ///< world, m/s^2 (used when `gravity`)
};
/// Reads q (+ alpha, alphaD per terms); fills `tau`. On a large tree (SharedPasses::largeTree) it
/// computes everything in place (no shared pass called).
EmittedBody rneaBody(const RobotModel & rm, const RneaTerms & terms);
/// The body of detail::inverse_dynamics_from: inverse dynamics under gravity from the header's
/// shared kernels `K` (a parameter), alpha and alphaD; fills `tau`.
EmittedBody inverseDynamicsFromKernelsBody(const RobotModel & rm);
/// `S(9.81)`: the magnitude of a plain header's gravity, as detail::inverse_dynamics_from takes it.
std::string gravityLiteral();
/// Reads q, alpha, alphaD and `fext[b]` (a wrench on each link, world coordinates at the world
/// origin); declares and fills `tau`: detail::inverse_dynamics_from minus the wrenches' torques
/// (passes::worldWrenchTorques).
EmittedBody inverseDynamicsWrenchesBody(const RobotModel & rm);

/// The mass matrix H (composite rigid-body algorithm, plus diag(armature) when given, per dof) as
/// the body of `detail::mass_matrix_lower(q, put)`: reads q, calls put(r, c, H(r, c)) for every
/// entry of the lower triangle (r >= c) that is not structurally zero, as soon as it is computed; nnz: their count;
/// slots: the initialiser lines of detail::mass_matrix_slot (nv x nv, row-major: the call index of
/// H(r, c) = H(c, r), -1 for a structural zero); entries: the initialiser of mass_matrix_entries ({row, col}
/// per call, a line per row of H).
struct MassMatrixLower
{
  EmittedBody body;
  int nnz = 0;
  std::string slots;
  std::string entries;
};
MassMatrixLower massMatrixLowerBody(const RobotModel & rm, const std::vector<double> & armature = {});
/// The public packed mass matrix (templates/mass_matrix_packed.hpp.in: MassMatrixEntry, mass_matrix_nnz,
/// mass_matrix_entries, mass_matrix_packed(q)), placed after mass_matrix: from `sparse`'s
/// detail::mass_matrix_lower (its entries, nv x nv = nv2), or, with nullptr (coupled mimic joints), the
/// whole lower triangle of mass_matrix(q).
std::string massMatrixPackedText(const MassMatrixLower * sparse, int nv);
/// Options of the CRBA + LTDL forward dynamics (the plain header uses the defaults).
struct FdOptions
{
  /// Statement right-hand side giving the bias C (Tangent<S>) subtracted from tau; empty: no bias.
  std::string biasCall = "nonlinear_effects<S>(q, alpha)";
  std::vector<double> armature; ///< per dof, added to the diagonal of H (empty: none)
  /// H from the header's detail::mass_matrix_lower (same armature) instead of its own CRBA columns.
  bool massMatrixLower = false;
};
/// Reads q, alpha, tau; fills `alphaD` from (H + diag(armature)) alphaD = tau - C (H by CRBA, C by
/// `biasCall`, tree-sparse L^T D L factorisation).
EmittedBody forwardDynamicsBody(const RobotModel & rm, const FdOptions & opt = {});
/// Lower triangle of H + diag(armature) (CRBA) as symbols, H[r][c] for c <= r; entry(r, c, H_rc), when
/// given, runs as each entry is emitted (leaves' columns first), e.g. to store it at once.
std::vector<std::vector<cg::Scalar>> emitMassMatrix(cg::Block & b, const RobotModel & rm, const std::vector<double> & armature,
                                                    const std::function<void(int r, int c, const cg::Scalar & x)> & entry = {});
/// Parent of each dof in the dof tree (Featherstone's λ on dofs), -1 for a root dof.
std::vector<int> dofParents(const RobotModel & rm);
/// H = L^T D L, tree-sparse (Featherstone, RBDA 6.5): L[k][i] for i an ancestor dof of k, 1/D.
struct Ltdl
{
  std::vector<std::vector<cg::Scalar>> L;
  std::vector<cg::Scalar> invD;
  std::vector<int> lambda;
  /// the ancestors of dof i in the dof tree (lambda), the root first, i excluded
  std::vector<std::size_t> ancestorsRootFirst(std::size_t i) const;
};
/// Factorise the lower triangle H (from emitMassMatrix).
Ltdl emitLtdl(cg::Block & b, const RobotModel & rm, std::vector<std::vector<cg::Scalar>> H);
/// x <- H^-1 x with the factors of emitLtdl.
std::vector<cg::Scalar> emitLtdlSolve(cg::Block & b, const Ltdl & f, std::vector<cg::Scalar> x);
/// Reads q, alpha, tau; fills `alphaD` (articulated-body algorithm).
EmittedBody abaBody(const RobotModel & rm);

/// The columns of joint mj (world axes, at the world point p) into `J`, given its world pose X0:
/// [R s_w; R s_v + (R s_w) x (p - o)], R = E_0^T, o = X0's origin.
void writePointColumns(cg::Block & b, const MovingJoint & mj, const passes::JointKernel & K, const cg::Xform & X0,
                       const cg::Vec3 & p);
/// Reads `kin` (Kinematics<S>) and `body` (Body); fills `J` (6 x nv, world axes at the link origin).
EmittedBody jacobianBody(const RobotModel & rm);
/// The header's detail functions for Jacobians from q (plain and scene headers): put_rotation,
/// put_column (a support step's column moved to the point, by kind), zero_columns, world_point, one
/// step function per moving joint (detail::support_step_<tag>, passes::supportStepFunctions: its
/// columns stored by kind), one function per link walking its support path, and
/// detail::support_jacobian(body, q, point, J), the switch over the links that fills the columns of
/// the link's support path in `J` (world axes, at `point` given in link coordinates) and zeros the others.
std::string supportJacobianDefinitions(const RobotModel & rm);
/// Reads `kin`; returns the centre of mass in world coordinates in `com`.
EmittedBody centerOfMassBody(const RobotModel & rm);
/// Reads q; returns the centre of mass in `com` (joint frames only, no link poses).
EmittedBody centerOfMassFromConfigBody(const RobotModel & rm);

/// Reads q, alpha; fills `res[b]` (link velocities, link coordinates).
EmittedBody bodyVelocitiesBody(const RobotModel & rm);
/// Reads q, alpha, alphaD; fills `res[b]` (link accelerations without gravity, link coordinates).
EmittedBody bodyAccelerationsBody(const RobotModel & rm);
/// Reads `kin`; fills `J` (3 x nv CoM Jacobian).
EmittedBody comJacobianBody(const RobotModel & rm);
/// Reads q; fills `A` (6 x nv centroidal momentum matrix, [angular about the CoM; linear]).
EmittedBody centroidalMomentumMatrixBody(const RobotModel & rm);

} // namespace rbdgen::emit
