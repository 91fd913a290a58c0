// Forward kinematics, link velocities and accelerations: the forward motion pass, written out per link.
#include <fmt/format.h>

#include "../passes/ForwardMotion.h"
#include "../passes/SharedPasses.h"
#include "Functions.h"
#include "Outputs.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

EmittedBody finish(const Block & b)
{
  return {b.str("  "), OpCount{b.mults(), b.adds(), b.calls()}};
}

namespace
{

// A link's section in a per-link output: headed by the link's name unless it is one statement that
// names the link already (`<dst>[detail::at(Body::<link>)]`, the link on the world or in its owner's
// frame).
void linkSection(Block & b, const BodyFrame & bf)
{
  if(bf.ident != bf.name || (bf.owner >= 0 && !bf.atOwnerFrame())) b.comment(fmt::format("link '{}'", bf.name));
}

// Link poses X_0_link = X_owner_link X_0_owner into `<dst>[Body::link]`.
void writeLinkPoses(PassContext & ctx, const MotionState & m, const std::string & dst)
{
  const RobotModel & rm = ctx.model();
  for(std::size_t i = 0; i < rm.bodies.size(); ++i)
  {
    linkSection(ctx.block(), rm.bodies[i]);
    writePose(ctx.block(), linkSlot(rm, dst, static_cast<int>(i)), linkPose(ctx, m, static_cast<int>(i)));
  }
}

// Velocities (or accelerations without gravity) of every link, link coordinates at its origin.
EmittedBody linkMotions(const RobotModel & rm, bool acceleration)
{
  Block b;
  PassContext ctx(b, rm);
  const MotionState m = forwardMotion(ctx, MotionRequest::make(false, true, acceleration), ctx.allJoints());
  for(std::size_t i = 0; i < rm.bodies.size(); ++i)
  {
    const BodyFrame & bf = rm.bodies[i];
    const std::string dst = linkSlot(rm, "res", static_cast<int>(i));
    linkSection(b, bf);
    if(bf.owner < 0)
    {
      b.line(dst + ".setZero();");
      continue;
    }
    const auto o = static_cast<std::size_t>(bf.owner);
    writeMotion(b, dst, apply(b, linkXform(bf), acceleration ? m.a[o] : m.v[o], "L_" + bf.ident));
  }
  return finish(b);
}

} // namespace

EmittedBody forwardKinematicsBody(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm);
  writeLinkPoses(ctx, forwardMotion(ctx, MotionRequest::make(true, false, false), ctx.allJoints()), "res");
  return finish(b);
}

std::string linkPosesDefinition(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm);
  ctx.kernelsFromCaller(); // (X0s holds what the poses read)
  ctx.fromCaller(SharedPasses::posesCall());
  writeLinkPoses(ctx, forwardMotion(ctx, MotionRequest::make(true, false, false), ctx.allJoints()), "res");
  return fmt::format("/// World pose of every link from the world poses of the joints' body frames (forward_kinematics\n"
                     "/// and kinematics).\n"
                     "template<class S>\n"
                     "RBDGEN_INLINE void link_poses([[maybe_unused]] const JointPoses<S> & X0s, std::array<Pose<S>, nbodies> & res) noexcept\n"
                     "{{\n{}}}",
                     b.str("  "));
}

EmittedBody linkPosesCallBody(const RobotModel & rm, const std::string & dst, bool frames)
{
  Block b;
  PassContext ctx(b, rm);
  const MotionState m = forwardMotion(ctx, MotionRequest::make(true, false, false), ctx.allJoints());
  if(frames)
    for(std::size_t k = 0; k < rm.joints.size(); ++k) writePose(b, fmt::format("kin.frame[{}]", k), m.X0[k]);
  b.line(fmt::format("detail::link_poses<S>({}, {});", rm.joints.empty() ? "detail::JointPoses<S>{}" : "X0s", dst));
  return finish(b);
}

EmittedBody bodyVelocitiesBody(const RobotModel & rm)
{
  return linkMotions(rm, false);
}

EmittedBody bodyAccelerationsBody(const RobotModel & rm)
{
  return linkMotions(rm, true);
}

} // namespace rbdgen::emit
