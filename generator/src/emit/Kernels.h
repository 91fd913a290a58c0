#pragma once
// Per-joint kernels and shared passes, written on symbolic spatial quantities: whatever is known
// at generation time (axes, constant transforms, inertias, zero inputs) folds away.

#include <string>
#include <vector>

#include "../codegen/Spatial.h"
#include "../model/RobotModel.h"

namespace rbdgen::emit
{

using namespace rbdgen::cg;

/// Joint transform X_j(q) and motion subspace columns of one moving joint.
struct JointKernel
{
  Xform Xj;               ///< from the joint frame (predecessor side) to the body frame
  std::vector<Motion> S;  ///< one column per dof, body coordinates
};

/// Emit the kernel of joint mj reading q from the expression `q` (e.g. "q").
JointKernel emitJointKernel(Block & b, const MovingJoint & mj, const std::string & q);

/// Kernels of every moving joint.
std::vector<JointKernel> emitKernels(Block & b, const RobotModel & rm, const std::string & q);

/// X_p_i m = X_j (X_T m): motion from the parent body frame to joint k's body frame.
Motion toChild(Block & b, const MovingJoint & mj, const JointKernel & K, const Motion & m, const std::string & hint);
/// X_p_i^T f = X_T^T (X_j^T f): force from joint k's body frame to its parent body frame.
Force toParent(Block & b, const MovingJoint & mj, const JointKernel & K, const Force & f, const std::string & hint);

/// World pose X_0_k of every moving joint's body: X_0_k = X_j (X_T X_0_p).
std::vector<Xform> emitWorldPoses(Block & b, const RobotModel & rm, const std::vector<JointKernel> & K);

/// Sum of S columns times the entries v[offset + d] of a vector expression named `v`.
Motion jointMotion(Block & b, const JointKernel & K, const std::string & v, int offset, const std::string & hint);

/// S^T f for each column.
std::vector<Scalar> projectForce(Block & b, const JointKernel & K, const Force & f, const std::string & hint);

/// Constant transform.
Xform constantXform(const sva::PTransformd & X);

/// "Rev about z", "Free", ... for comments.
std::string describeJoint(const MovingJoint & mj);

} // namespace rbdgen::emit
