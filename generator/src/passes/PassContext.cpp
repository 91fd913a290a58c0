#include "PassContext.h"

#include <fmt/format.h>

namespace rbdgen::passes
{

PassContext::PassContext(Block & b, const RobotModel & rm, std::string q)
: b_(b), rm_(rm), q_(std::move(q)), kernels_(rm.joints.size())
{
}

const JointKernel & PassContext::kernel(int k)
{
  auto & K = kernels_[static_cast<std::size_t>(k)];
  if(!K)
  {
    const MovingJoint & mj = joint(k);
    b_.comment(fmt::format("{}: joint '{}' ({})", mj.tag, mj.name, describeJoint(mj)));
    K = emitJointKernel(b_, mj, q_);
  }
  return *K;
}

std::vector<int> PassContext::allJoints() const
{
  std::vector<int> all(rm_.joints.size());
  for(std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  return all;
}

} // namespace rbdgen::passes
