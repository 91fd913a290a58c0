// Link Jacobians and Jdot alpha along the support path of a link given at run time, from
// precomputed kinematics (leaf to root by direct jumps) or from q (root to leaf over the path
// table, nothing computed off the path), and the Jacobian of the centre of mass.
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
  emitLinkPoseFromWalk(b, rm, true, false);
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

namespace
{

// [A_w; A_v + A_w x p + V_w x (V_v + V_w x p)]: angular acceleration and the classical
// acceleration of point p, from the spatial velocity V and acceleration A at the world origin.
void writePointAcceleration(Block & b, const Vec3 & p, const Motion & V, const Motion & A)
{
  b.comment("angular: A_w; classical acceleration of the point p: A_v + A_w x p + V_w x (V_v + V_w x p)");
  const Vec3 vp = add(b, V.v, cross(b, V.w, p, "Vwxp"), "vp");
  const Vec3 lin = add(b, add(b, A.v, cross(b, A.w, p, "Awxp"), "ap"), cross(b, V.w, vp, "Vwxvp"), "acc");
  writeMotion(b, "res", {A.w, lin});
}

// Accumulate a symbolic motion into a mutable Eigen 6-vector: `<dst>(i) += m_i;`.
void accumulate(Block & b, const std::string & dst, const Motion & m)
{
  for(int c = 0; c < 3; ++c)
  {
    if(!m.w[c].isZero()) b.line(fmt::format("{}({}) += {};", dst, c, Block::text(m.w[c])));
    if(!m.v[c].isZero()) b.line(fmt::format("{}({}) += {};", dst, c + 3, Block::text(m.v[c])));
  }
}

} // namespace

EmittedBody jacobianDotTimesAlphaBody(const RobotModel & rm)
{
  // World frame (Pluecker coordinates at the world origin). Joint k's velocity contribution is
  // C_k = X_0_k^-1 (S_k alpha_k); the link's velocity is V = sum of C_k over its path and, at
  // alphaD = 0, its acceleration is A = sum_k V_k x C_k with V_k the sum up to k (the body-frame
  // recursion a_k = X a_p + v_k x vJ_k, summed in world coordinates). Writing V_k = V - U_k, U_k the
  // sum of the contributions leafward of k, and V x V = 0: A = sum_k C_k x U_k, accumulated while
  // walking from the link to the root (U += C_k after the term).
  Block b;
  b.line("const Eigen::Matrix<S, 3, 1> p = kin.pose[detail::at(body)].translation;");
  b.line("Eigen::Matrix<S, 6, 1> U = Eigen::Matrix<S, 6, 1>::Zero(), A = Eigen::Matrix<S, 6, 1>::Zero();");
  const Motion U{vec3Var("U", 0), vec3Var("U", 3)}, A{vec3Var("A", 0), vec3Var("A", 3)};
  emitJumpWalk(b, rm, "jd", "A += C x U, U += C", [&](int k, const MovingJoint & mj) {
    const JointKernel K = emitJointKernel(b, mj, "kin.q");
    const Motion vJ = jointMotion(b, K, "alpha", mj.vIndex, mj.tag + "_vJ");
    const Motion C = invApply(b, kinFrame(k), vJ, mj.tag + "_C");
    accumulate(b, "A", cross(b, C, U, mj.tag + "_CxU"));
    accumulate(b, "U", C);
  });
  writePointAcceleration(b, vec3Var("p"), U, A);
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
