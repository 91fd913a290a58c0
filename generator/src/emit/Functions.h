#pragma once
// Bodies of the emitted functions. Each returns the statements of one function body (indented),
// written from the robot model with every recursion unrolled.

#include <string>

#include "../codegen/Expr.h"
#include "../model/RobotModel.h"

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
/// Reads q; fills `kin.pose[b]` (links) and `kin.frame[k]` (moving joints' body frames).
EmittedBody kinematicsBody(const RobotModel & rm);

/// Which terms of the recursive Newton-Euler algorithm are present.
struct RneaTerms
{
  bool velocity = true;      ///< alpha (Coriolis, centrifugal)
  bool acceleration = true;  ///< alphaD
  bool gravity = true;
  bool externalForces = false; ///< `fext[b]`: wrench on each link, world coordinates at the world origin
};
/// Reads q (+ alpha, alphaD, fext per terms); fills `tau`.
EmittedBody rneaBody(const RobotModel & rm, const RneaTerms & terms);

/// Reads q; fills `H` (composite rigid-body algorithm).
EmittedBody massMatrixBody(const RobotModel & rm);
/// Reads q, alpha, tau; fills `alphaD` (H by CRBA, C by RNEA, tree-sparse L^T D L factorisation).
EmittedBody forwardDynamicsBody(const RobotModel & rm);
/// Reads q, alpha, tau; fills `alphaD` (articulated-body algorithm).
EmittedBody abaBody(const RobotModel & rm);

/// Reads `kin` (Kinematics<S>) and `b` (Body); fills `J` (6 x nv, world axes at the link origin).
EmittedBody jacobianBody(const RobotModel & rm);
/// Reads `kin`; returns the centre of mass in world coordinates in `com`.
EmittedBody centerOfMassBody(const RobotModel & rm);

/// Reads q, alpha; fills `res[b]` (link velocities, link coordinates).
EmittedBody bodyVelocitiesBody(const RobotModel & rm);
/// Reads q, alpha, alphaD; fills `res[b]` (link accelerations without gravity, link coordinates).
EmittedBody bodyAccelerationsBody(const RobotModel & rm);
/// Reads `body`, q, alpha; fills `res` (Jdot alpha at the link origin, world axes).
EmittedBody jacobianDotTimesAlphaBody(const RobotModel & rm);
/// Reads `kin`; fills `J` (3 x nv CoM Jacobian).
EmittedBody comJacobianBody(const RobotModel & rm);
/// Reads q; fills `A` (6 x nv centroidal momentum matrix, [angular about the CoM; linear]).
EmittedBody centroidalMomentumMatrixBody(const RobotModel & rm);

} // namespace rbdgen::emit
