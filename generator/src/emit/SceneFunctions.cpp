// Bodies of the functions a scene adds: scene inverse dynamics / bias (RNEA with the scene's
// gravity, velocity terms, joint effects, contact and wrench forces), contact forces, and the
// requested outputs. Whatever the scene disables is never emitted.
#include <fmt/format.h>

#include "Kernels.h"
#include "SceneEffects.h"

namespace rbdgen::emit
{

bool SceneEffects::anyNonZero(const std::vector<double> & v) const
{
  for(double x : v)
    if(x != 0.0) return true;
  return false;
}

namespace
{

// World poses along the path of moving joint `owner` only (others left identity).
std::vector<Xform> emitPathPoses(Block & b, const RobotModel & rm, int owner, std::vector<JointKernel> & K)
{
  std::vector<Xform> X0(rm.joints.size(), Xform::identity());
  K.assign(rm.joints.size(), JointKernel{});
  for(int k : rm.path(owner))
  {
    const auto kk = static_cast<std::size_t>(k);
    const MovingJoint & mj = rm.joints[kk];
    K[kk] = emitJointKernel(b, mj, "q");
    const Xform Xt = constantXform(mj.Xt);
    const Xform X_0_t = mj.parent < 0 ? Xt : compose(b, Xt, X0[static_cast<std::size_t>(mj.parent)], mj.tag + "_X0t");
    X0[kk] = compose(b, K[kk].Xj, X_0_t, mj.tag + "_X0");
  }
  return X0;
}

// The contact point in its owner's body frame (constant): X_owner_link^-1 applied to the point.
Vec3 contactPointInOwner(const RobotModel & rm, const SceneContact & c)
{
  const sva::PTransformd & X = rm.bodies[static_cast<std::size_t>(c.body)].X_owner_link;
  return Vec3::constant(X.translation() + X.rotation().transpose() * c.point);
}

// World force of the compliant contact model at a point of world position p and velocity pd:
//   d = h - p_z, vn = pd_z, fn = max(0, k d - c vn) if d > 0 else 0,
//   ft = -mu fn vt / sqrt(|vt|^2 + v_slip^2), vt = (pd_x, pd_y).
Vec3 emitContactForce(Block & b, const SceneEffects & fx, const Vec3 & p, const Vec3 & pd, const std::string & h)
{
  const Scalar d = b.sum({Term{fx.groundHeight, {}}, Term{-1.0, {p[2]}}}, h + "_depth");
  const Scalar push = b.sum({Term{fx.stiffness, {d}}, Term{-fx.contactDamping, {pd[2]}}}, h + "_push");
  const std::string dt = Block::text(d), pt = Block::text(push);
  const Scalar fn = b.def(fmt::format("{} > S(0) && {} > S(0) ? {} : S(0)", dt, pt, pt), h + "_fn");
  Vec3 f = Vec3::zero();
  f[2] = fn;
  if(fx.mu != 0.0)
  {
    const Scalar vt2 = b.sum({Term{1.0, {pd[0], pd[0]}}, Term{1.0, {pd[1], pd[1]}},
                              Term{fx.slipVelocity * fx.slipVelocity, {}}}, h + "_vt2");
    const Scalar g = b.def(fmt::format("{} * {} / std::sqrt({})", Block::literal(-fx.mu), Block::text(fn), Block::text(vt2)),
                           h + "_mu");
    f[0] = mul(b, g, pd[0], h + "_fx");
    f[1] = mul(b, g, pd[1], h + "_fy");
  }
  return f;
}

// Point of a moving body: world position r + E^T p and velocity E^T (v + w x p) (body velocity v).
void emitPointMotion(Block & b, const Xform & X0, const Motion & v, const Vec3 & p, Vec3 & pos, Vec3 & vel,
                     const std::string & h)
{
  pos = add(b, X0.r, tmul(b, X0.E, p, h + "_Rp"), h + "_p");
  vel = tmul(b, X0.E, add(b, v.v, cross(b, v.w, p, h + "_wxp"), h + "_vb"), h + "_pd");
}

} // namespace

EmittedBody sceneRneaBody(const RobotModel & rm, const SceneEffects & fx, bool withAlphaD)
{
  Block b;
  const auto K = emitKernels(b, rm, "q");
  const bool contacts = !fx.contacts.empty(), wrenches = !fx.wrenchBodies.empty();
  std::vector<Xform> X0;
  if(contacts || wrenches) X0 = emitWorldPoses(b, rm, K);
  const bool needV = fx.velocityTerms || contacts; // contact point velocities need v
  const std::size_t n = rm.joints.size();
  std::vector<Motion> v(n, Motion::zero()), a(n);
  std::vector<Force> f(n);
  // a_0 = [0; -g]: gravity as a fictitious acceleration of the world (RBDyn).
  Motion a0 = Motion::zero();
  if(fx.gravity)
    for(int c = 0; c < 3; ++c) a0.v[c] = Scalar::constant(-(*fx.gravity)[c]);
  for(std::size_t k = 0; k < n; ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    const std::string t = mj.tag;
    const auto p = static_cast<std::size_t>(mj.parent);
    b.comment(fmt::format("{} forward pass: v = X_p_i v_p + S alpha, a = X_p_i a_p + S alphaD{}", t,
                          fx.velocityTerms ? " + v x S alpha" : ""));
    const Motion vJ = needV ? jointMotion(b, K[k], "alpha", mj.vIndex, t + "_vJ") : Motion::zero();
    if(needV) v[k] = add(b, toChild(b, mj, K[k], mj.parent < 0 ? Motion::zero() : v[p], t + "_Xv"), vJ, t + "_v");
    const Motion aJ = withAlphaD ? jointMotion(b, K[k], "alphaD", mj.vIndex, t + "_aJ") : Motion::zero();
    a[k] = add(b, toChild(b, mj, K[k], mj.parent < 0 ? a0 : a[p], t + "_Xa"), aJ, t + "_aa");
    const Inertia I = constantInertia(mj.inertia.mass(), mj.inertia.momentum(), mj.inertia.inertia());
    // f = I a (+ v x* I v)
    if(fx.velocityTerms) a[k] = add(b, a[k], cross(b, v[k], vJ, t + "_vxvJ"), t + "_a");
    f[k] = apply(b, I, a[k], t + "_Ia");
    if(fx.velocityTerms) f[k] = add(b, f[k], crossDual(b, v[k], apply(b, I, v[k], t + "_Iv"), t + "_vxIv"), t + "_f");
  }
  for(std::size_t w = 0; w < fx.wrenchBodies.size(); ++w)
  {
    const int o = rm.bodies[static_cast<std::size_t>(fx.wrenchBodies[w])].owner;
    if(o < 0) continue; // a wrench on a link that never moves does nothing
    b.comment(fmt::format("wrench {} on '{}': f -= X_0_i^* w (world coordinates at the world origin)", w,
                          rm.bodies[static_cast<std::size_t>(fx.wrenchBodies[w])].name));
    Force fe;
    for(int c = 0; c < 3; ++c)
    {
      fe.n[c] = Scalar::var(fmt::format("wrenches[{}][{}]", w, c));
      fe.f[c] = Scalar::var(fmt::format("wrenches[{}][{}]", w, c + 3));
    }
    const auto ko = static_cast<std::size_t>(o);
    f[ko] = sub(b, f[ko], dualApply(b, X0[ko], fe, fmt::format("w{}_b", w)), rm.joints[ko].tag + "_fw");
  }
  for(std::size_t c = 0; c < fx.contacts.size(); ++c)
  {
    const SceneContact & sc = fx.contacts[c];
    const int o = rm.bodies[static_cast<std::size_t>(sc.body)].owner;
    if(o < 0) continue;
    const auto ko = static_cast<std::size_t>(o);
    const std::string h = fmt::format("c{}", c);
    b.comment(fmt::format("contact '{}': world force fc at point p (owner frame): f -= [p x E fc; E fc]", sc.name));
    const Vec3 p = contactPointInOwner(rm, sc);
    Vec3 pos, vel;
    emitPointMotion(b, X0[ko], v[ko], p, pos, vel, h);
    const Vec3 fc = emitContactForce(b, fx, pos, vel, h);
    const Vec3 fb = mul(b, X0[ko].E, fc, h + "_fb");
    f[ko] = sub(b, f[ko], Force{cross(b, p, fb, h + "_nb"), fb}, rm.joints[ko].tag + "_fc");
  }
  for(std::size_t k = n; k-- > 0;)
  {
    const MovingJoint & mj = rm.joints[k];
    b.comment(fmt::format("{} backward pass: tau = S^T f, f_p += X_p_i^T f", mj.tag));
    const auto tau = projectForce(b, K[k], f[k], mj.tag + "_tau");
    for(int d = 0; d < mj.nv; ++d)
    {
      const int i = mj.vIndex + d;
      const auto ii = static_cast<std::size_t>(i);
      std::vector<Term> terms{Term{1.0, {tau[static_cast<std::size_t>(d)]}}};
      const std::string al = fmt::format("alpha[{}]", i);
      if(withAlphaD && ii < fx.armature.size())
        terms.push_back(Term{fx.armature[ii], {Scalar::var(fmt::format("alphaD[{}]", i))}});
      if(ii < fx.damping.size()) terms.push_back(Term{fx.damping[ii], {Scalar::var(al)}});
      if(ii < fx.friction.size() && fx.friction[ii] != 0.0)
        // Coulomb friction, regularised: friction alpha / sqrt(alpha^2 + v_s^2)
        terms.push_back(Term{1.0, {b.def(fmt::format("{} * {} / std::sqrt({} * {} + {})", Block::literal(fx.friction[ii]), al, al,
                                                     al, Block::literal(fx.frictionVelocity * fx.frictionVelocity)),
                                         fmt::format("fr{}", i))}});
      b.line(fmt::format("tau[{}] = {};", i, Block::text(terms)));
    }
    if(mj.parent >= 0)
    {
      const auto p = static_cast<std::size_t>(mj.parent);
      f[p] = add(b, f[p], toParent(b, mj, K[k], f[k], mj.tag + "_fp"), rm.joints[p].tag + "_f");
    }
  }
  return finish(b);
}

EmittedBody contactForcesBody(const RobotModel & rm, const SceneEffects & fx)
{
  Block b;
  const auto K = emitKernels(b, rm, "q");
  const auto X0 = emitWorldPoses(b, rm, K);
  const std::size_t n = rm.joints.size();
  std::vector<Motion> v(n, Motion::zero());
  for(std::size_t k = 0; k < n; ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    const Motion vJ = jointMotion(b, K[k], "alpha", mj.vIndex, mj.tag + "_vJ");
    const Motion vp = mj.parent < 0 ? Motion::zero() : v[static_cast<std::size_t>(mj.parent)];
    v[k] = add(b, toChild(b, mj, K[k], vp, mj.tag + "_Xv"), vJ, mj.tag + "_v");
  }
  for(std::size_t c = 0; c < fx.contacts.size(); ++c)
  {
    const SceneContact & sc = fx.contacts[c];
    const int o = rm.bodies[static_cast<std::size_t>(sc.body)].owner;
    const std::string h = fmt::format("c{}", c);
    b.comment(fmt::format("contact '{}'", sc.name));
    const Vec3 p = contactPointInOwner(rm, sc);
    Vec3 pos = p, vel = Vec3::zero(); // a static body: the point is fixed in the world
    if(o >= 0) emitPointMotion(b, X0[static_cast<std::size_t>(o)], v[static_cast<std::size_t>(o)], p, pos, vel, h);
    const Vec3 fc = emitContactForce(b, fx, pos, vel, h);
    for(int i = 0; i < 3; ++i) b.line(fmt::format("res[{}][{}] = {};", c, i, Block::text(fc[i])));
  }
  return finish(b);
}

EmittedBody linkPoseBody(const RobotModel & rm, int body)
{
  Block b;
  const BodyFrame & bf = rm.bodies[static_cast<std::size_t>(body)];
  const Xform C = constantXform(bf.X_owner_link);
  Xform X = C;
  if(bf.owner >= 0)
  {
    std::vector<JointKernel> K;
    const auto X0 = emitPathPoses(b, rm, bf.owner, K);
    X = compose(b, C, X0[static_cast<std::size_t>(bf.owner)], "X0_" + bf.ident);
  }
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) b.line(fmt::format("res.rotation({}, {}) = {};", r, c, Block::text(X.E(r, c))));
  for(int i = 0; i < 3; ++i) b.line(fmt::format("res.translation({}) = {};", i, Block::text(X.r[i])));
  return finish(b);
}

EmittedBody linkJacobianBody(const RobotModel & rm, int body)
{
  Block b;
  const BodyFrame & bf = rm.bodies[static_cast<std::size_t>(body)];
  if(bf.owner < 0) return finish(b);
  std::vector<JointKernel> K;
  const auto X0 = emitPathPoses(b, rm, bf.owner, K);
  const Xform Xl = compose(b, constantXform(bf.X_owner_link), X0[static_cast<std::size_t>(bf.owner)], "X0_link");
  for(int k : rm.path(bf.owner))
  {
    const auto kk = static_cast<std::size_t>(k);
    const MovingJoint & mj = rm.joints[kk];
    const std::string h = "J_" + mj.tag;
    const Vec3 po = sub(b, Xl.r, X0[kk].r, h + "_po");
    for(int d = 0; d < mj.nv; ++d)
    {
      // column: [R s_w; R s_v + (R s_w) x (p - o_k)], R = E_0_k^T
      const Motion & Sd = K[kk].S[static_cast<std::size_t>(d)];
      const Vec3 w = tmul(b, X0[kk].E, Sd.w, fmt::format("{}_w{}", h, d));
      const Vec3 vv = add(b, tmul(b, X0[kk].E, Sd.v, fmt::format("{}_Rv{}", h, d)), cross(b, w, po, fmt::format("{}_wxp{}", h, d)),
                          fmt::format("{}_v{}", h, d));
      for(int r = 0; r < 3; ++r)
      {
        if(!w[r].isZero()) b.line(fmt::format("J({}, {}) = {};", r, mj.vIndex + d, Block::text(w[r])));
        if(!vv[r].isZero()) b.line(fmt::format("J({}, {}) = {};", r + 3, mj.vIndex + d, Block::text(vv[r])));
      }
    }
  }
  return finish(b);
}

namespace
{

// Body velocities (body coordinates) and world poses of every moving joint.
void emitVelocities(Block & b, const RobotModel & rm, std::vector<Xform> & X0, std::vector<Motion> & v)
{
  const auto K = emitKernels(b, rm, "q");
  X0 = emitWorldPoses(b, rm, K);
  v.assign(rm.joints.size(), Motion::zero());
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    const Motion vJ = jointMotion(b, K[k], "alpha", mj.vIndex, mj.tag + "_vJ");
    const Motion vp = mj.parent < 0 ? Motion::zero() : v[static_cast<std::size_t>(mj.parent)];
    v[k] = add(b, toChild(b, mj, K[k], vp, mj.tag + "_Xv"), vJ, mj.tag + "_v");
  }
}

Inertia inertiaOf(const MovingJoint & mj)
{
  return constantInertia(mj.inertia.mass(), mj.inertia.momentum(), mj.inertia.inertia());
}

} // namespace

namespace
{

// Sum over every link of m c (world), static ones included.
Vec3 emitFirstMoments(Block & b, const RobotModel & rm, const std::vector<Xform> & X0)
{
  Vec3 moment = Vec3::constant(rm.staticMoment);
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    if(mj.inertia.mass() == 0.0) continue;
    moment = add(b, moment, add(b, tmul(b, X0[k].E, Vec3::constant(mj.inertia.momentum()), mj.tag + "_h"),
                                scale(b, Scalar::constant(mj.inertia.mass()), X0[k].r, mj.tag + "_mo"), mj.tag + "_mc"),
                 mj.tag + "_sum");
  }
  return moment;
}

} // namespace

EmittedBody centerOfMassQBody(const RobotModel & rm)
{
  Block b;
  const auto K = emitKernels(b, rm, "q");
  const auto X0 = emitWorldPoses(b, rm, K);
  const Vec3 moment = emitFirstMoments(b, rm, X0);
  const double invM = rm.totalMass > 0 ? 1.0 / rm.totalMass : 0.0;
  for(int c = 0; c < 3; ++c)
    b.line(fmt::format("com({}) = {};", c, Block::text(b.sum({Term{invM, {moment[c]}}}, fmt::format("com_{}", c)))));
  return finish(b);
}

EmittedBody centroidalMomentumBody(const RobotModel & rm)
{
  Block b;
  std::vector<Xform> X0;
  std::vector<Motion> v;
  emitVelocities(b, rm, X0, v);
  // h_O = sum_k X_0_k^T (I_k v_k) (world axes, at the world origin); first moment for the CoM
  Force hO = Force::zero();
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    hO = add(b, hO, transApply(b, X0[k], apply(b, inertiaOf(mj), v[k], mj.tag + "_Iv"), mj.tag + "_hw"), mj.tag + "_hO");
  }
  const Vec3 moment = emitFirstMoments(b, rm, X0);
  const double invM = rm.totalMass > 0 ? 1.0 / rm.totalMass : 0.0;
  const Vec3 com = scale(b, Scalar::constant(invM), moment, "com");
  b.comment("about the centre of mass: n_G = n_O - com x f");
  const Vec3 nG = sub(b, hO.n, cross(b, com, hO.f, "cxf"), "nG");
  for(int r = 0; r < 3; ++r)
  {
    b.line(fmt::format("h[{}] = {};", r, Block::text(nG[r])));
    b.line(fmt::format("h[{}] = {};", r + 3, Block::text(hO.f[r])));
  }
  return finish(b);
}

EmittedBody energyBody(const RobotModel & rm, const SceneEffects & fx, bool kinetic)
{
  Block b;
  std::vector<Xform> X0;
  std::vector<Motion> v;
  emitVelocities(b, rm, X0, v);
  if(kinetic)
  {
    b.comment(fx.hasArmature() ? "sum_k v_k^T I_k v_k / 2 + sum_i armature_i alpha_i^2 / 2" : "sum_k v_k^T I_k v_k / 2");
    std::vector<Term> ek;
    for(std::size_t k = 0; k < rm.joints.size(); ++k)
    {
      const MovingJoint & mj = rm.joints[k];
      const Force Iv = apply(b, inertiaOf(mj), v[k], mj.tag + "_Iv");
      for(int i = 0; i < 3; ++i)
      {
        ek.push_back(Term{0.5, {v[k].w[i], Iv.n[i]}});
        ek.push_back(Term{0.5, {v[k].v[i], Iv.f[i]}});
      }
    }
    for(std::size_t i = 0; i < fx.armature.size(); ++i)
      if(fx.armature[i] != 0.0)
      {
        const Scalar a = Scalar::var(fmt::format("alpha[{}]", i));
        ek.push_back(Term{0.5 * fx.armature[i], {a, a}});
      }
    b.line("e = " + Block::text(b.sum(ek, "kinetic")) + ";");
    return finish(b);
  }
  b.comment("-g . (sum of m c over every link, static ones included), world");
  const Vec3 moment = emitFirstMoments(b, rm, X0);
  const Eigen::Vector3d g = fx.gravity ? *fx.gravity : Eigen::Vector3d::Zero();
  b.line("e = " + Block::text(b.sum({Term{-g[0], {moment[0]}}, Term{-g[1], {moment[1]}}, Term{-g[2], {moment[2]}}}, "potential")) + ";");
  return finish(b);
}

} // namespace rbdgen::emit
