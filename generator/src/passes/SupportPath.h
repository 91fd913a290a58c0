#pragma once
// Support paths: the moving joints that move one link, from the root to the link's owner.
// Functions that take a `Body` at run time walk only that link's path, with each joint's block
// emitted once (code grows with the number of joints, not with the sum of the path lengths):
//  - from precomputed kinematics (kin.frame[k]), leaf to root by direct jumps (emitJumpWalk);
//  - from q, root to leaf over a constexpr table of paths (emitPathLoop): one batched sin/cos of
//    the path's angles, then one `case` per joint updating the world pose of the walk.

#include <functional>
#include <string>
#include <vector>

#include "PassContext.h"

namespace rbdgen::passes
{

/// The constexpr tables of the header's detail namespace that emitPathLoop reads:
/// support_depth[body], support_path[body][i] (root first), angle_index[joint] (q index of the
/// joint's angle, 0 when it has none), max_support_depth, dof_begin[joint] and dof_count[joint] (its velocity coordinates).
std::string supportPathTables(const RobotModel & rm);

/// Leaf to root from link `body` (a run-time value named `body`):
///   switch(body) { case Body::<link>: goto <prefix>_<owner>; ... }
///   <prefix>_<joint>: { // joint '<name>': <what>
///   jointBlock(k) } goto <prefix>_<parent>; ... <prefix>_done:;
void emitJumpWalk(Block & b, const RobotModel & rm, const std::string & prefix, const std::string & what,
                  const std::function<void(int k, const MovingJoint & mj)> & jointBlock);

/// Root to leaf along the support path of link `body` (a run-time value), reading q from `q`.
/// Declares `Eigen::Matrix<S, 3, 3> walk_E` and `Eigen::Matrix<S, 3, 1> walk_o`, the world pose
/// (rotation, origin) of the last body visited (world at the start), and the loop index `walk_i`.
/// jointBlock(k, kernel, X0) emits joint k's work given its kernel and its body's world pose X0;
/// walk_E / walk_o are updated after it. Returns the symbolic world pose of the walk's end.
Xform emitPathLoop(Block & b, const RobotModel & rm, const std::string & q,
                   const std::function<void(int k, const JointKernel & K, const Xform & X0)> & jointBlock);

/// The world origin of link `body` (`link_o`) and, with rotation, its rotation (`link_E`), from the
/// pose of its owner at the end of a path loop: a switch over the links, constants folded.
void emitLinkPoseFromWalk(Block & b, const RobotModel & rm, bool rotation);

} // namespace rbdgen::passes
