#include "BackwardForce.h"

#include <fmt/format.h>

#include "SharedPasses.h"

namespace rbdgen::passes
{

Eigen::Matrix3d symmetricInertia(const MovingJoint & mj)
{
  const Eigen::Matrix3d I = mj.inertia.inertia();
  return 0.5 * (I + I.transpose());
}

Inertia bodyInertia(const MovingJoint & mj)
{
  const std::string c = "model::" + mj.tag;
  const Eigen::Vector3d h = mj.inertia.momentum();
  const Eigen::Matrix3d I = symmetricInertia(mj);
  Inertia o;
  o.m = Scalar::named(mj.inertia.mass(), c + ".m");
  for(int r = 0; r < 3; ++r)
  {
    o.h[r] = Scalar::named(h[r], fmt::format("{}.h{}", c, "xyz"[r]));
    for(int k = 0; k < 3; ++k) o.I(r, k) = Scalar::named(I(r, k), fmt::format("{}.I{}{}", c, r, k));
  }
  return o;
}

Force inertialForce(PassContext & ctx, const MotionState & m, bool velocityProducts, int k)
{
  Block & b = ctx.block();
  const auto kk = static_cast<std::size_t>(k);
  const MovingJoint & mj = ctx.joint(k);
  const std::string & t = mj.tag;
  const Inertia I = bodyInertia(mj);
  b.comment(fmt::format("{}: f = I a{}", t, velocityProducts ? " + v x* I v" : ""));
  const Force Ia = apply(b, I, m.a[kk], t + "_Ia");
  if(!velocityProducts) return Ia;
  // v x* I v from the header's shared velocity products when m's velocities are the shared ones
  if(m.sharedVelocities) ctx.callOnce("[[maybe_unused]] const auto VPs = detail::velocity_products<S>(Vs);");
  const Force p = m.sharedVelocities ? ctx.shared()->velocityProducts().p[kk]
                                     : crossDual(b, m.v[kk], apply(b, I, m.v[kk], t + "_Iv"), t + "_vxIv");
  return add(b, Ia, p, t + "_f");
}

std::vector<Force> inertialForces(PassContext & ctx, const MotionState & m, bool velocityProducts,
                                  const std::vector<int> & joints)
{
  std::vector<Force> f(ctx.model().joints.size(), Force::zero());
  for(int k : joints) f[static_cast<std::size_t>(k)] = inertialForce(ctx, m, velocityProducts, k);
  return f;
}

void subtractWorldWrench(PassContext & ctx, std::vector<Force> & f, const MotionState & m, int body, const Force & w,
                         const std::string & hint)
{
  const int o = ctx.model().bodies[static_cast<std::size_t>(body)].owner;
  if(o < 0) return;
  const auto ko = static_cast<std::size_t>(o);
  Block & b = ctx.block();
  f[ko] = sub(b, f[ko], dualApply(b, m.X0[ko], w, hint), ctx.joint(o).tag + "_fe");
}

void subtractPointForce(PassContext & ctx, std::vector<Force> & f, const MotionState & m, int owner, const Vec3 & p,
                        const Vec3 & fc, const std::string & hint)
{
  Block & b = ctx.block();
  const auto ko = static_cast<std::size_t>(owner);
  const Vec3 fb = mul(b, m.X0[ko].E, fc, hint + "_fb");
  f[ko] = sub(b, f[ko], Force{cross(b, p, fb, hint + "_nb"), fb}, ctx.joint(owner).tag + "_fc");
}

void backwardForces(PassContext & ctx, std::vector<Force> & f,
                    const std::function<void(int k, const std::vector<Scalar> & tau)> & onTau)
{
  Block & b = ctx.block();
  for(std::size_t k = f.size(); k-- > 0;)
  {
    const int kk = static_cast<int>(k);
    const MovingJoint & mj = ctx.joint(kk);
    const JointKernel & K = ctx.kernel(kk);
    b.comment(fmt::format("{} backward: tau = S^T f, f_p += X_p_i^T f", mj.tag));
    onTau(kk, projectForce(b, K, f[k], mj.tag + "_tau"));
    if(mj.parent >= 0)
    {
      const auto p = static_cast<std::size_t>(mj.parent);
      f[p] = add(b, f[p], toParent(b, mj, K, f[k], mj.tag + "_fp"), ctx.joint(mj.parent).tag + "_f");
    }
  }
}

void worldWrenchTorques(PassContext & ctx, const std::vector<Xform> & X0, const std::vector<std::string> & linkWrench,
                        const std::function<void(int k, const std::vector<Scalar> & tau)> & onTau)
{
  Block & b = ctx.block();
  const RobotModel & rm = ctx.model();
  // the terms of W_k: its own links' wrenches (body order), then its children's W (leaves first)
  std::vector<std::string> terms(rm.joints.size());
  auto addTerm = [&](int k, const std::string & x) {
    std::string & t = terms[static_cast<std::size_t>(k)];
    t += (t.empty() ? "" : " + ") + x;
  };
  for(std::size_t i = 0; i < rm.bodies.size(); ++i)
    if(const int o = rm.bodies[i].owner; o >= 0) addTerm(o, linkWrench[i]); // (a link that never moves takes no wrench)
  b.comment("W_k: the wrenches on joint k's subtree (world coordinates at the world origin)");
  std::vector<Force> W(rm.joints.size());
  for(std::size_t k = W.size(); k-- > 0;)
  {
    const std::string name = ctx.joint(static_cast<int>(k)).tag + "_W";
    b.line(fmt::format("const Wrench<S> {} = {};", name, terms[k]));
    for(int i = 0; i < 3; ++i)
    {
      W[k].n[i] = Scalar::var(fmt::format("{}({})", name, i));
      W[k].f[i] = Scalar::var(fmt::format("{}({})", name, i + 3));
    }
    if(const int p = rm.joints[k].parent; p >= 0) addTerm(p, name);
  }
  b.comment("tau_ext,k = S_k^T X_0_k^* W_k");
  for(std::size_t k = 0; k < W.size(); ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    onTau(static_cast<int>(k), projectForce(b, ctx.kernel(static_cast<int>(k)), dualApply(b, X0[k], W[k], mj.tag + "_XW"), mj.tag + "_tauW"));
  }
}

std::function<void(int, const std::vector<Scalar> &)> writeTorques(PassContext & ctx, const std::string & dst)
{
  return [&ctx, dst](int k, const std::vector<Scalar> & tau) {
    const MovingJoint & mj = ctx.joint(k);
    for(int d = 0; d < mj.nv; ++d)
      ctx.block().line(fmt::format("{}[{}] = {};", dst, mj.vIndex + d, Block::text(tau[static_cast<std::size_t>(d)])));
  };
}

} // namespace rbdgen::passes
