#pragma once
// Support paths: the moving joints that move one link, from the root to the link's owner.
// Functions that take a `Body` at run time walk only that link's path, with each joint's block
// emitted once:
//  - from precomputed kinematics (kin.frame[k]), leaf to root by direct jumps (emitJumpWalk);
//  - from q, root to leaf: one function per link calling one step function per joint of its path
//    (supportStepFunctions, emitLinkWalk), so each link's walk is straight-line code with its
//    path, angles and columns known at compile time (one call line per joint of each path: the
//    sum of the path lengths, 416 for talos_reduced with a free base).

#include <functional>
#include <string>
#include <vector>

#include "PassContext.h"

namespace rbdgen::passes
{

/// The constexpr tables of the header's detail namespace that loops over a path read (e.g.
/// detail::jdot_from_columns): support_depth[body], support_path[body][i] (root first),
/// max_support_depth, dof_begin[joint] and dof_count[joint] (its velocity coordinates).
std::string supportPathTables(const RobotModel & rm);

/// Leaf to root from link `body` (a run-time value named `body`):
///   switch(body) { case Body::<link>: goto <prefix>_<owner>; ... }
///   <prefix>_<joint>: // joint '<name>': <what>
///   jointBlock(jb, k) [goto <prefix>_<parent>;] ... [<prefix>_done:;]
/// jointBlock writes joint k's statements into jb (between braces when they declare locals); the
/// jump to the parent is left out where the parent's block comes next.
void emitJumpWalk(Block & b, const RobotModel & rm, const std::string & prefix, const std::string & what,
                  const std::function<void(Block & jb, int k, const MovingJoint & mj)> & jointBlock);

/// The walk from q along support paths, one step function per moving joint (emitted once; the
/// path switch calls them, and they inline into a straight line per link):
///   template<class S> RBDGEN_INLINE void <prefix>_<tag>([const Config<S> & q, ][const S & s, const S & c, ]
///       Pose<S> & X<extraParams(joint)>) noexcept
/// takes the walk's pose X from the world pose of the joint's parent body (the identity for a joint
/// on the world, whose step does not read it) to the joint's body; s and c are
/// the sin and cos of its angle (joints with one), q is read by the joints that are not revolute.
/// jointBlock(b, k, K, X0) emits the joint's own work between the two, given its kernel K and its
/// body's world pose X0.
std::string supportStepFunctions(const RobotModel & rm, const std::string & prefix,
                                 const std::function<std::string(const MovingJoint &)> & extraParams,
                                 const std::function<void(Block & b, int k, const JointKernel & K, const Xform & X0)> & jointBlock);

/// The walk from q to link bf (straight-line code, its path known at generation time): the sin and
/// cos of the path's angles (read from q in contiguous runs: detail::sincos_span), then the pose
/// `walk` advanced by one <prefix>_<tag>(..., walk<extraArgs(joint)>) call per joint of the
/// path, root first. Returns the link's symbolic world pose (its constant offset from its owner
/// folded; a constant for a link on the world, whose path is empty).
Xform emitLinkWalk(Block & b, const RobotModel & rm, const BodyFrame & bf, const std::string & prefix,
                   const std::function<std::string(const MovingJoint &)> & extraArgs);

} // namespace rbdgen::passes
