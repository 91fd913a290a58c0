#pragma once
// Per-joint kernels and the spatial steps every pass takes across a joint, written on symbolic spatial quantities: whatever is known
// at generation time (axes, constant transforms, inertias, zero inputs) folds away.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "../codegen/Spatial.h"
#include "../model/RobotModel.h"

namespace rbdgen::passes
{

using namespace rbdgen::cg;

/// Joint transform X_j(q) and motion subspace columns of one moving joint.
struct JointKernel
{
  Xform Xj;               ///< from the joint frame (predecessor side) to the body frame
  std::vector<Motion> S;  ///< one column per dof, body coordinates
};

/// sin and cos of a joint angle, given the angle's index in q.
using AngleSinCos = std::function<std::pair<Scalar, Scalar>(int qIndex)>;

/// Emit the kernel of joint mj reading q from the expression `q` (e.g. "q"); angles' sin and cos
/// from `angles` when given, else `std::sin(q[i])` statements (batched by Block::str).
JointKernel emitJointKernel(Block & b, const MovingJoint & mj, const std::string & q, const AngleSinCos & angles = {});

/// X_p_i m = X_j (X_T m): motion from the parent body frame to joint k's body frame.
Motion toChild(Block & b, const MovingJoint & mj, const JointKernel & K, const Motion & m, const std::string & hint);
/// X_p_i^T f = X_T^T (X_j^T f): force from joint k's body frame to its parent body frame.
Force toParent(Block & b, const MovingJoint & mj, const JointKernel & K, const Force & f, const std::string & hint);

/// Sum of S columns times the entries v[offset + d] of a vector expression named `v`.
Motion jointMotion(Block & b, const JointKernel & K, const std::string & v, int offset, const std::string & hint);

/// S^T f for each column.
std::vector<Scalar> projectForce(Block & b, const JointKernel & K, const Force & f, const std::string & hint);

/// Constant transform.
Xform constantXform(const sva::PTransformd & X);
/// Joint mj's constant transform X_T from its parent body frame, entries named after the header's
/// model constants (`model::<tag>.E01`, `model::<tag>.ry`; see modelConstants).
Xform treeXform(const MovingJoint & mj);
/// The constant transform from link bf's owner's body frame to the link frame (links on fixed joints),
/// entries named `model::L_<ident>.E01`, `.ry`.
Xform linkXform(const BodyFrame & bf);
/// The `model` namespace of a header: one constexpr JointConstants per moving joint (X_T and the
/// inertia of the body it moves) and one LinkConstants per link off its owner's frame, the values
/// treeXform, linkXform and bodyInertia name.
std::string modelConstants(const RobotModel & rm);

/// "Rev about z", "Free", ... for comments.
std::string describeJoint(const MovingJoint & mj);

} // namespace rbdgen::passes
