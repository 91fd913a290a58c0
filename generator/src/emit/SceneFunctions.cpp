// Bodies of the functions a scene adds: scene inverse dynamics / bias (RNEA with the scene's
// gravity, velocity terms, joint effects, contact and wrench forces), contact forces, and the
// requested outputs. Whatever the scene disables is never emitted.
#include <fmt/format.h>

#include "../passes/BackwardForce.h"
#include "../passes/CompositeInertia.h"
#include "Outputs.h"
#include "SceneEffects.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

bool SceneEffects::anyNonZero(const std::vector<double> & v) const
{
  for(double x : v)
    if(x != 0.0) return true;
  return false;
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
  const Scalar fn = b.def(cg::lanesSelect(cg::lanesBoth(dt + " > S(0)", pt + " > S(0)"), pt, "S(0)"), h + "_fn");
  Vec3 f = Vec3::zero();
  f[2] = fn;
  if(fx.mu != 0.0)
  {
    const Scalar vt2 = b.sum({Term{1.0, {pd[0], pd[0]}}, Term{1.0, {pd[1], pd[1]}},
                              Term{fx.slipVelocity * fx.slipVelocity, {}}}, h + "_vt2");
    const Scalar g = b.def(fmt::format("{} * {} / {}", Block::literal(-fx.mu), Block::text(fn), cg::lanesSqrt(Block::text(vt2))),
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

EmittedBody sceneRneaBody(const RobotModel & rm, const SceneEffects & fx, bool withAlphaD)
{
  Block b;
  PassContext ctx(b, rm);
  const bool contacts = !fx.contacts.empty(), wrenches = !fx.wrenchBodies.empty();
  MotionRequest req;
  req.poses = contacts || wrenches;
  req.velocity = fx.velocityTerms || contacts; // contact point velocities need v
  req.acceleration = true;
  req.alphaD = withAlphaD;
  req.velocityProducts = fx.velocityTerms;
  req.gravity = fx.gravity;
  // each joint's inertial force right after its motion (fewer values live at once)
  std::vector<Force> f(rm.joints.size(), Force::zero());
  const MotionState m = forwardMotion(ctx, req, ctx.allJoints(), [&](int k, const MotionState & mk) {
    f[static_cast<std::size_t>(k)] = inertialForce(ctx, mk, fx.velocityTerms, k);
  });
  for(std::size_t w = 0; w < fx.wrenchBodies.size(); ++w)
  {
    const int body = fx.wrenchBodies[w];
    b.comment(fmt::format("wrench {} on '{}': f -= X_0_i^* w (world coordinates at the world origin)", w,
                          rm.bodies[static_cast<std::size_t>(body)].name));
    const std::string slot = fmt::format("wrenches[{}]", w);
    subtractWorldWrench(ctx, f, m, body, {vec3Var(slot, 0), vec3Var(slot, 3)}, fmt::format("w{}_b", w));
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
    emitPointMotion(b, m.X0[ko], m.v[ko], p, pos, vel, h);
    subtractPointForce(ctx, f, m, o, p, emitContactForce(b, fx, pos, vel, h), h);
  }
  backwardForces(ctx, f, [&](int k, const std::vector<Scalar> & tau) {
    const MovingJoint & mj = rm.joints[static_cast<std::size_t>(k)];
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
        terms.push_back(Term{1.0, {b.def(fmt::format("{} * {} / {}", Block::literal(fx.friction[ii]), al,
                                                     cg::lanesSqrt(fmt::format("{} * {} + {}", al, al,
                                                                               Block::literal(fx.frictionVelocity * fx.frictionVelocity)))),
                                         fmt::format("fr{}", i))}});
      b.line(fmt::format("tau[{}] = {};", i, Block::text(terms)));
    }
  });
  return finish(b);
}

EmittedBody contactForcesBody(const RobotModel & rm, const SceneEffects & fx)
{
  Block b;
  PassContext ctx(b, rm);
  const MotionState m = forwardMotion(ctx, MotionRequest::make(true, true, false), ctx.allJoints());
  for(std::size_t c = 0; c < fx.contacts.size(); ++c)
  {
    const SceneContact & sc = fx.contacts[c];
    const int o = rm.bodies[static_cast<std::size_t>(sc.body)].owner;
    const std::string h = fmt::format("c{}", c);
    b.comment(fmt::format("contact '{}'", sc.name));
    const Vec3 p = contactPointInOwner(rm, sc);
    Vec3 pos = p, vel = Vec3::zero(); // a static body: the point is fixed in the world
    if(o >= 0) emitPointMotion(b, m.X0[static_cast<std::size_t>(o)], m.v[static_cast<std::size_t>(o)], p, pos, vel, h);
    const Vec3 fc = emitContactForce(b, fx, pos, vel, h);
    for(int i = 0; i < 3; ++i) b.line(fmt::format("res[{}][{}] = {};", c, i, Block::text(fc[i])));
  }
  return finish(b);
}

EmittedBody linkPoseBody(const RobotModel & rm, int body)
{
  Block b;
  PassContext ctx(b, rm);
  const int owner = rm.bodies[static_cast<std::size_t>(body)].owner;
  const MotionState m = forwardMotion(ctx, MotionRequest::make(true, false, false), owner < 0 ? std::vector<int>{} : rm.path(owner));
  writePose(b, "res", linkPose(ctx, m, body));
  return finish(b);
}

EmittedBody linkJacobianBody(const RobotModel & rm, int body)
{
  Block b;
  PassContext ctx(b, rm);
  const BodyFrame & bf = rm.bodies[static_cast<std::size_t>(body)];
  if(bf.owner < 0) return finish(b);
  const std::vector<int> path = rm.path(bf.owner);
  const MotionState m = forwardMotion(ctx, MotionRequest::make(true, false, false), path);
  const Xform Xl = linkPose(ctx, m, body);
  for(int k : path) writePointColumns(b, rm.joints[static_cast<std::size_t>(k)], ctx.kernel(k), m.X0[static_cast<std::size_t>(k)], Xl.r);
  return finish(b);
}

EmittedBody centerOfMassQBody(const RobotModel & rm)
{
  return centerOfMassFromConfigBody(rm);
}

EmittedBody centroidalMomentumBody(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm);
  const MotionState m = forwardMotion(ctx, MotionRequest::make(true, true, false), ctx.allJoints());
  // h_O = sum_k X_0_k^T (I_k v_k) (world axes, at the world origin)
  Force hO = Force::zero();
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    hO = add(b, hO, transApply(b, m.X0[k], apply(b, bodyInertia(mj), m.v[k], mj.tag + "_Iv"), mj.tag + "_hw"), mj.tag + "_hO");
  }
  const Vec3 com = centerOfMass(ctx, m.X0);
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
  PassContext ctx(b, rm);
  const MotionState m = forwardMotion(ctx, MotionRequest::make(!kinetic, kinetic, false), ctx.allJoints());
  if(kinetic)
  {
    b.comment(fx.hasArmature() ? "sum_k v_k^T I_k v_k / 2 + sum_i armature_i alpha_i^2 / 2" : "sum_k v_k^T I_k v_k / 2");
    std::vector<Term> ek;
    for(std::size_t k = 0; k < rm.joints.size(); ++k)
    {
      const MovingJoint & mj = rm.joints[k];
      const Force Iv = apply(b, bodyInertia(mj), m.v[k], mj.tag + "_Iv");
      for(int i = 0; i < 3; ++i)
      {
        ek.push_back(Term{0.5, {m.v[k].w[i], Iv.n[i]}});
        ek.push_back(Term{0.5, {m.v[k].v[i], Iv.f[i]}});
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
  const Vec3 moment = totalFirstMoment(ctx, m.X0);
  const Eigen::Vector3d g = fx.gravity ? *fx.gravity : Eigen::Vector3d::Zero();
  b.line("e = " + Block::text(b.sum({Term{-g[0], {moment[0]}}, Term{-g[1], {moment[1]}}, Term{-g[2], {moment[2]}}}, "potential")) + ";");
  return finish(b);
}

} // namespace rbdgen::emit
