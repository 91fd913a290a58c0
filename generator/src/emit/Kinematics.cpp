// Forward kinematics, link velocities and accelerations: the forward motion pass, written out per link.
#include <fmt/format.h>

#include "../passes/ForwardMotion.h"
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

// Link poses X_0_link = X_owner_link X_0_owner into `<dst>[Body::link]`.
void writeLinkPoses(PassContext & ctx, const MotionState & m, const std::string & dst)
{
  const RobotModel & rm = ctx.model();
  for(std::size_t i = 0; i < rm.bodies.size(); ++i)
  {
    ctx.block().comment(fmt::format("link '{}'", rm.bodies[i].name));
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
    b.comment(fmt::format("link '{}'", bf.name));
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

EmittedBody kinematicsBody(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm);
  const MotionState m = forwardMotion(ctx, MotionRequest::make(true, false, false), ctx.allJoints());
  for(std::size_t k = 0; k < rm.joints.size(); ++k) writePose(b, fmt::format("kin.frame[{}]", k), m.X0[k]);
  writeLinkPoses(ctx, m, "kin.pose");
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
