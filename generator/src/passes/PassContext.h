#pragma once
// What the passes of one emitted function body share: the statement block, the robot model and
// the joint kernels X_j(q), S(q). Kernels come, in this order of preference, from the caller
// (`given`: a shared pass's own body), from the header's shared passes (SharedPasses::current():
// one call of detail::joint_kernels), or are emitted here, each at its first use (a function
// that walks one support path emits only that path's kernels).

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "JointKernels.h"

namespace rbdgen::passes
{

class SharedPasses;

class PassContext
{
public:
  /// q: the C++ expression of the configuration in the emitted body ("q", "kin.q").
  PassContext(Block & b, const RobotModel & rm, std::string q = "q");
  /// Kernels given symbolically (no sharing, nothing emitted for them).
  PassContext(Block & b, const RobotModel & rm, const std::vector<JointKernel> & given);

  Block & block() { return b_; }
  const RobotModel & model() const { return rm_; }
  const MovingJoint & joint(int k) const { return rm_.joints[static_cast<std::size_t>(k)]; }
  /// Kernel of moving joint k (emitted, with a comment naming the joint, at its first use).
  const JointKernel & kernel(int k);
  /// Every moving joint, root first.
  std::vector<int> allJoints() const;

  /// The header's shared passes when this body may call them (nullptr otherwise).
  SharedPasses * shared() const { return shared_; }
  /// Emit `line` (a call of a shared pass) unless this body already has it.
  void callOnce(const std::string & line);
  /// The body receives the shared kernels as a parameter `K` (a detail function of the header):
  /// the call of detail::joint_kernels is not emitted.
  void kernelsFromCaller();
  /// This body emits every pass in place (no shared pass called; kernels at their first use).
  void emitInPlace() { shared_ = nullptr; }
  /// The body receives what `line` (a call of a shared pass) declares as a parameter: not emitted.
  void fromCaller(const std::string & line);

private:
  std::string kernelsCall() const;
  Block & b_;
  const RobotModel & rm_;
  std::string q_;
  const std::vector<JointKernel> * given_ = nullptr;
  SharedPasses * shared_ = nullptr;
  std::vector<std::optional<JointKernel>> kernels_;
  std::set<std::string> calls_;
};

} // namespace rbdgen::passes
