// Centre of mass (from precomputed kinematics or from q) and the centroidal momentum matrix:
// the forward pose pass, first moments of mass and the composite-inertia pass.
#include <fmt/format.h>

#include "../passes/CompositeInertia.h"
#include "Functions.h"
#include "Outputs.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

namespace
{

void writeCom(Block & b, const Vec3 & com)
{
  for(int c = 0; c < 3; ++c) b.line(fmt::format("com({}) = {};", c, Block::text(com[c])));
}

} // namespace

EmittedBody centerOfMassBody(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm, "kin.q");
  std::vector<Xform> X0;
  for(std::size_t k = 0; k < rm.joints.size(); ++k) X0.push_back(kinFrame(static_cast<int>(k)));
  writeCom(b, centerOfMass(ctx, X0));
  return finish(b);
}

EmittedBody centerOfMassFromConfigBody(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm);
  b.comment("joint frames only: the link poses of kinematics() are not needed");
  writeCom(b, centerOfMass(ctx, forwardMotion(ctx, MotionRequest::make(true, false, false), ctx.allJoints()).X0));
  return finish(b);
}

EmittedBody centroidalMomentumMatrixBody(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm);
  const std::vector<Xform> X0 = forwardMotion(ctx, MotionRequest::make(true, false, false), ctx.allJoints()).X0;
  const std::vector<Inertia> Ic = compositeInertias(ctx);
  const Vec3 com = centerOfMassFromComposites(ctx, X0, Ic);
  // Column: momentum of the subtree moving with S: X_0_j^T (Ic_j S) in world at the origin, then
  // about the CoM: n_G = n_O - com x f.
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    for(int d = 0; d < mj.nv; ++d)
    {
      const std::string h = fmt::format("{}_A{}", mj.tag, d);
      const Force F = apply(b, Ic[k], ctx.kernel(static_cast<int>(k)).S[static_cast<std::size_t>(d)], h + "_F");
      const Force Fw = transApply(b, X0[k], F, h + "_Fw");
      writeColumn(b, "A", mj.vIndex + d, sub(b, Fw.n, cross(b, com, Fw.f, h + "_cxf"), h + "_nG"), Fw.f);
    }
  }
  return finish(b);
}

} // namespace rbdgen::emit
