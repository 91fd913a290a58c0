#include "PassContext.h"

#include <fmt/format.h>

#include "SharedPasses.h"

namespace rbdgen::passes
{

PassContext::PassContext(Block & b, const RobotModel & rm, std::string q)
: b_(b), rm_(rm), q_(std::move(q)), shared_(SharedPasses::current()), kernels_(rm.joints.size())
{
}

PassContext::PassContext(Block & b, const RobotModel & rm, const std::vector<JointKernel> & given)
: b_(b), rm_(rm), given_(&given), kernels_(rm.joints.size())
{
}

const JointKernel & PassContext::kernel(int k)
{
  if(given_) return (*given_)[static_cast<std::size_t>(k)];
  if(shared_)
  {
    callOnce(kernelsCall());
    return shared_->kernels()[static_cast<std::size_t>(k)];
  }
  auto & K = kernels_[static_cast<std::size_t>(k)];
  if(!K)
  {
    const MovingJoint & mj = joint(k);
    b_.comment(fmt::format("{}: joint '{}' ({})", mj.tag, mj.name, describeJoint(mj)));
    K = emitJointKernel(b_, mj, q_);
  }
  return *K;
}

std::string PassContext::kernelsCall() const
{
  return fmt::format("[[maybe_unused]] const auto K = detail::joint_kernels<S>({});", q_);
}

void PassContext::kernelsFromCaller()
{
  calls_.insert(kernelsCall());
}

void PassContext::fromCaller(const std::string & line)
{
  calls_.insert(line);
}

void PassContext::callOnce(const std::string & line)
{
  if(calls_.insert(line).second) b_.line(line);
}

std::vector<int> PassContext::allJoints() const
{
  std::vector<int> all(rm_.joints.size());
  for(std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  return all;
}

} // namespace rbdgen::passes
