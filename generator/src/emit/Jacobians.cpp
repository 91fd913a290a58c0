// Link Jacobians along the support path of a link given at run time, from precomputed kinematics
// (leaf to root by direct jumps) or from q (root to leaf over the path table, nothing computed off
// the path; Jdot alpha is computed from these columns by the header's detail::jdot_from_columns),
// and the Jacobian of the centre of mass.
#include <fmt/format.h>

#include "../passes/CompositeInertia.h"
#include "../passes/SupportPath.h"
#include "Functions.h"
#include "Outputs.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

namespace
{

// Columns of joint k at the world origin, world axes: w = R s_w, u = R s_v - w x o_k
// (R = E_0_k^T, o_k its origin); the column at a point p is [w; u + w x p].
void writeOriginColumns(Block & b, const MovingJoint & mj, const JointKernel & K, const Xform & X0)
{
  for(int d = 0; d < mj.nv; ++d)
  {
    const Motion & Sd = K.S[static_cast<std::size_t>(d)];
    const std::string h = fmt::format("J_{}_{}", mj.tag, d);
    const Vec3 w = tmul(b, X0.E, Sd.w, h + "_w");
    const Vec3 u = sub(b, tmul(b, X0.E, Sd.v, h + "_Rv"), cross(b, w, X0.r, h + "_wxo"), h + "_u");
    writeColumn(b, "J", mj.vIndex + d, w, u);
  }
}

// The point p (world) of link `body` after a path loop: its origin, or the given point in link coordinates.
void declarePoint(Block & b, const RobotModel & rm, bool withPoint)
{
  emitLinkPoseFromWalk(b, rm, withPoint);
  b.line(withPoint ? "const Eigen::Matrix<S, 3, 1> p = link_o + link_E.transpose() * point;"
                   : "const Eigen::Matrix<S, 3, 1> & p = link_o;");
}

} // namespace

void writePointColumns(Block & b, const MovingJoint & mj, const JointKernel & K, const Xform & X0, const Vec3 & p)
{
  // [R s_w; R s_v + (R s_w) x (p - o_k)],  R = E_0_k^T, o_k = origin of joint k's frame
  const std::string h = fmt::format("J_{}", mj.tag);
  const Vec3 po = sub(b, p, X0.r, h + "_po");
  for(int d = 0; d < mj.nv; ++d)
  {
    const Motion & Sd = K.S[static_cast<std::size_t>(d)];
    const Vec3 w = tmul(b, X0.E, Sd.w, fmt::format("{}_w{}", h, d));
    const Vec3 v = add(b, tmul(b, X0.E, Sd.v, fmt::format("{}_Rv{}", h, d)), cross(b, w, po, fmt::format("{}_wxp{}", h, d)),
                       fmt::format("{}_v{}", h, d));
    writeColumn(b, "J", mj.vIndex + d, w, v);
  }
}

EmittedBody supportJacobianBody(const RobotModel & rm)
{
  Block b;
  emitPathLoop(b, rm, "q", [&](int k, const JointKernel & K, const Xform & X0) {
    writeOriginColumns(b, rm.joints[static_cast<std::size_t>(k)], K, X0);
  });
  emitLinkPoseFromWalk(b, rm, true);
  // (returned, not assigned to the caller's variables: declared before the walk, g++ 12 kept them
  // in memory and jacobian(q) of ur5 took 112 instead of 69 ns)
  b.line("return {link_E, link_o};");
  return finish(b);
}

EmittedBody jacobianBody(const RobotModel & rm)
{
  // Column of dof d of joint k (world axes, at the link origin p):
  //   [R s_w; R s_v + (R s_w) x (p - o_k)],  R = E_0_k^T, o_k = origin of joint k's frame.
  Block b;
  b.line("const Eigen::Matrix<S, 3, 1> p = kin.pose[detail::at(body)].translation;");
  const Vec3 p = vec3Var("p");
  emitJumpWalk(b, rm, "jac", "its columns", [&](int k, const MovingJoint & mj) {
    // S depends on q only for backward multi-dof joints
    writePointColumns(b, mj, emitJointKernel(b, mj, "kin.q"), kinFrame(k), p);
  });
  return finish(b);
}

EmittedBody jacobianFromConfigBody(const RobotModel & rm, bool withPoint)
{
  Block b;
  emitPathLoop(b, rm, "q", [&](int k, const JointKernel & K, const Xform & X0) {
    writeOriginColumns(b, rm.joints[static_cast<std::size_t>(k)], K, X0);
  });
  declarePoint(b, rm, withPoint);
  b.comment("move the path's columns from the world origin to p: v += w x p");
  b.line("for(int i = 0; i < walk_depth; ++i)");
  b.line("{");
  b.line("  const auto k = static_cast<std::size_t>(walk_path[static_cast<std::size_t>(i)]);");
  b.line("  for(int c = detail::dof_begin[k]; c < detail::dof_begin[k] + detail::dof_count[k]; ++c)");
  b.line("  {");
  b.line("    const S wx = J(0, c), wy = J(1, c), wz = J(2, c);");
  b.line("    J(3, c) += wy * p(2) - wz * p(1);");
  b.line("    J(4, c) += wz * p(0) - wx * p(2);");
  b.line("    J(5, c) += wx * p(1) - wy * p(0);");
  b.line("  }");
  b.line("}");
  return finish(b);
}

EmittedBody comJacobianBody(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm, "kin.q");
  const std::size_t n = rm.joints.size();
  // Subtree mass and first moment (world): M_j, h_j = sum over the subtree of m_k o_k + E_0_k^T h_k.
  std::vector<double> mass(n, 0.0);
  std::vector<Vec3> moment(n, Vec3::zero());
  for(std::size_t k = n; k-- > 0;)
  {
    const MovingJoint & mj = rm.joints[k];
    if(mj.inertia.mass() != 0.0) moment[k] = add(b, moment[k], firstMoment(ctx, static_cast<int>(k), kinFrame(static_cast<int>(k))), mj.tag + "_hs");
    mass[k] += mj.inertia.mass();
    if(mj.parent >= 0)
    {
      const auto p = static_cast<std::size_t>(mj.parent);
      mass[p] += mass[k];
      moment[p] = add(b, moment[p], moment[k], rm.joints[p].tag + "_hs");
    }
  }
  // Column of dof d of joint j: (w x (h_j - M_j o_j) + M_j R s_v) / M, with w = R s_w.
  const double invM = rm.totalMass > 0 ? 1.0 / rm.totalMass : 0.0;
  for(std::size_t k = 0; k < n; ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    const JointKernel & K = ctx.kernel(static_cast<int>(k));
    const Xform X0 = kinFrame(static_cast<int>(k));
    const Vec3 rel = sub(b, moment[k], scale(b, Scalar::constant(mass[k]), X0.r, mj.tag + "_Mo"), mj.tag + "_rel");
    for(int d = 0; d < mj.nv; ++d)
    {
      const Motion & Sd = K.S[static_cast<std::size_t>(d)];
      const std::string h = fmt::format("{}_c{}", mj.tag, d);
      const Vec3 w = tmul(b, X0.E, Sd.w, h + "_w");
      const Vec3 col = add(b, cross(b, w, rel, h + "_wxh"), scale(b, Scalar::constant(mass[k]), tmul(b, X0.E, Sd.v, h + "_Rv"), h + "_Mv"), h);
      for(int r = 0; r < 3; ++r)
      {
        const Scalar x = b.sum({Term{invM, {col[r]}}}, fmt::format("{}_{}", h, r));
        if(!x.isZero()) b.line(fmt::format("J({}, {}) = {};", r, mj.vIndex + d, Block::text(x)));
      }
    }
  }
  return finish(b);
}

} // namespace rbdgen::emit
