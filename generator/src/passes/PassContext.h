#pragma once
// What the passes of one emitted function body share: the statement block, the robot model and
// the joint kernels X_j(q), S(q), each emitted on first use (a function that walks one support
// path emits only that path's kernels).

#include <optional>
#include <string>
#include <vector>

#include "JointKernels.h"

namespace rbdgen::passes
{

class PassContext
{
public:
  /// q: the C++ expression of the configuration in the emitted body ("q", "kin.q").
  PassContext(Block & b, const RobotModel & rm, std::string q = "q");

  Block & block() { return b_; }
  const RobotModel & model() const { return rm_; }
  const MovingJoint & joint(int k) const { return rm_.joints[static_cast<std::size_t>(k)]; }
  /// Kernel of moving joint k (emitted, with a comment naming the joint, at its first use).
  const JointKernel & kernel(int k);
  /// Every moving joint, root first.
  std::vector<int> allJoints() const;

private:
  Block & b_;
  const RobotModel & rm_;
  std::string q_;
  std::vector<std::optional<JointKernel>> kernels_;
};

} // namespace rbdgen::passes
