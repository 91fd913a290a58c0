#include "ForwardMotion.h"

#include "SharedPasses.h"

namespace rbdgen::passes
{

MotionState forwardMotion(PassContext & ctx, const MotionRequest & req, const std::vector<int> & joints,
                          const std::function<void(int k, const MotionState & m)> & afterJoint)
{
  Block & b = ctx.block();
  const std::size_t n = ctx.model().joints.size();
  MotionState m{std::vector<Xform>(n, Xform::identity()), std::vector<Motion>(n, Motion::zero()),
                std::vector<Motion>(n, Motion::zero()), std::vector<Motion>(n, Motion::zero())};
  // Over every joint, poses and velocities come from the header's shared passes when it has them
  // (velocities only on small trees: see SharedPasses::largeTree).
  SharedPasses * shared = joints.size() == n && n > 0 ? ctx.shared() : nullptr;
  const bool sharedVelocities = shared && !SharedPasses::largeTree(ctx.model());
  if(shared && req.poses)
  {
    ctx.kernel(0); // declares K
    ctx.callOnce(SharedPasses::posesCall());
    m.X0 = shared->poses();
  }
  if(sharedVelocities && req.velocity)
  {
    ctx.kernel(0);
    ctx.callOnce("[[maybe_unused]] const auto Vs = detail::joint_velocities<S>(K, alpha);");
    m.vJ = shared->velocities().first;
    m.v = shared->velocities().second;
    m.sharedVelocities = true;
  }
  Motion a0 = Motion::zero();
  if(req.gravity && !req.gravityParameter.empty())
  {
    const Eigen::Vector3d up = -req.gravity->normalized();
    for(int c = 0; c < 3; ++c)
      a0.v[c] = b.sum({Term{up[c], {Scalar::var(req.gravityParameter)}}}, "a0_v_" + std::string(1, "xyz"[c]));
  }
  else if(req.gravity)
    for(int c = 0; c < 3; ++c) a0.v[c] = Scalar::constant(-(*req.gravity)[c]);
  for(int k : joints)
  {
    const auto kk = static_cast<std::size_t>(k);
    const MovingJoint & mj = ctx.joint(k);
    const JointKernel & K = ctx.kernel(k);
    const std::string & t = mj.tag;
    const bool root = mj.parent < 0;
    const auto p = static_cast<std::size_t>(root ? 0 : mj.parent);
    if(req.poses && !shared)
    {
      const Xform Xt = treeXform(mj);
      m.X0[kk] = compose(b, K.Xj, root ? Xt : compose(b, Xt, m.X0[p], t + "_X0t"), t + "_X0");
    }
    if(req.velocity && !sharedVelocities)
    {
      m.vJ[kk] = jointMotion(b, K, "alpha", mj.vIndex, t + "_vJ");
      m.v[kk] = add(b, toChild(b, mj, K, root ? Motion::zero() : m.v[p], t + "_Xv"), m.vJ[kk], t + "_v");
    }
    if(req.acceleration)
    {
      const Motion aJ = req.alphaD ? jointMotion(b, K, "alphaD", mj.vIndex, t + "_aJ") : Motion::zero();
      m.a[kk] = add(b, toChild(b, mj, K, root ? a0 : m.a[p], t + "_Xa"), aJ, t + "_aa");
      if(req.velocity && req.velocityProducts) m.a[kk] = add(b, m.a[kk], velocityProduct(ctx, m, k, t + "_vxvJ"), t + "_a");
    }
    if(afterJoint) afterJoint(k, m);
  }
  return m;
}

Motion velocityBias(Block & b, const MovingJoint & mj, const Motion & v, const Motion & vJ, const std::string & hint)
{
  return mj.parent < 0 ? Motion::zero() : cross(b, v, vJ, hint);
}

Motion velocityProduct(PassContext & ctx, const MotionState & m, int k, const std::string & hint)
{
  const auto kk = static_cast<std::size_t>(k);
  if(!m.sharedVelocities) return velocityBias(ctx.block(), ctx.joint(k), m.v[kk], m.vJ[kk], hint);
  ctx.callOnce("[[maybe_unused]] const auto VPs = detail::velocity_products<S>(Vs);");
  return ctx.shared()->velocityProducts().c[kk];
}

Xform linkPose(PassContext & ctx, const MotionState & m, int body)
{
  const BodyFrame & bf = ctx.model().bodies[static_cast<std::size_t>(body)];
  const Xform C = linkXform(bf);
  return bf.owner < 0 ? C : compose(ctx.block(), C, m.X0[static_cast<std::size_t>(bf.owner)], "X0_" + bf.ident);
}

} // namespace rbdgen::passes
