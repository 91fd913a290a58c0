#include "CompositeInertia.h"

#include <fmt/format.h>

#include "BackwardForce.h"
#include "SharedPasses.h"

namespace rbdgen::passes
{

std::vector<Inertia> compositeInertias(PassContext & ctx, const std::function<void(int k, const Inertia & Ic)> & final)
{
  Block & b = ctx.block();
  const RobotModel & rm = ctx.model();
  if(ctx.shared() && !rm.joints.empty())
  {
    ctx.kernel(0); // declares K
    ctx.callOnce("[[maybe_unused]] const auto Ics = detail::composite_inertias<S>(K);");
    const std::vector<Inertia> & Ic = ctx.shared()->compositeInertias();
    if(final)
      for(std::size_t k = rm.joints.size(); k-- > 0;) final(static_cast<int>(k), Ic[k]);
    return Ic;
  }
  std::vector<Inertia> Ic;
  for(const MovingJoint & mj : rm.joints) Ic.push_back(bodyInertia(mj));
  for(std::size_t k = rm.joints.size(); k-- > 0;)
  {
    // Ic_k is complete: every child has a larger index
    if(final) final(static_cast<int>(k), Ic[k]);
    const MovingJoint & mj = rm.joints[k];
    if(mj.parent < 0) continue;
    b.comment(fmt::format("{}: composite inertia into its parent, Ic_p += X_p_i^T Ic_i X_p_i", mj.tag));
    const Inertia Ij = transApply(b, ctx.kernel(static_cast<int>(k)).Xj, Ic[k], mj.tag + "_Icj");
    const Inertia Ip = transApply(b, treeXform(mj), Ij, mj.tag + "_Icp");
    const auto p = static_cast<std::size_t>(mj.parent);
    Ic[p] = add(b, Ic[p], Ip, rm.joints[p].tag + "_Ic");
  }
  return Ic;
}

Vec3 firstMoment(PassContext & ctx, int k, const Xform & X0)
{
  Block & b = ctx.block();
  const MovingJoint & mj = ctx.joint(k);
  const Inertia I = bodyInertia(mj);
  return add(b, tmul(b, X0.E, I.h, mj.tag + "_h"), scale(b, I.m, X0.r, mj.tag + "_mo"), mj.tag + "_mc");
}

Vec3 totalFirstMoment(PassContext & ctx, const std::vector<Xform> & X0)
{
  const RobotModel & rm = ctx.model();
  Vec3 sum = Vec3::constant(rm.staticMoment);
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
    if(rm.joints[k].inertia.mass() != 0.0)
      sum = add(ctx.block(), sum, firstMoment(ctx, static_cast<int>(k), X0[k]), rm.joints[k].tag + "_sum");
  return sum;
}

Vec3 centerOfMass(PassContext & ctx, const std::vector<Xform> & X0)
{
  const double M = ctx.model().totalMass;
  ctx.block().comment("com = (sum_k m_k o_k + E_0_k^T h_k + static first moment) / M");
  return scale(ctx.block(), Scalar::constant(M > 0 ? 1.0 / M : 0.0), totalFirstMoment(ctx, X0), "com");
}

Vec3 centerOfMassFromComposites(PassContext & ctx, const std::vector<Xform> & X0, const std::vector<Inertia> & Ic)
{
  Block & b = ctx.block();
  const RobotModel & rm = ctx.model();
  b.comment("com = (sum over the root joints r of Mc_r o_r + E_0_r^T hc_r + static first moment) / M");
  Vec3 sum = Vec3::constant(rm.staticMoment);
  for(std::size_t r = 0; r < rm.joints.size(); ++r)
  {
    if(rm.joints[r].parent >= 0) continue;
    const std::string & t = rm.joints[r].tag;
    sum = add(b, sum, add(b, tmul(b, X0[r].E, Ic[r].h, t + "_hc"), scale(b, Ic[r].m, X0[r].r, t + "_Mo"), t + "_mc"), t + "_sum");
  }
  const double M = rm.totalMass;
  return scale(b, Scalar::constant(M > 0 ? 1.0 / M : 0.0), sum, "com");
}

} // namespace rbdgen::passes
