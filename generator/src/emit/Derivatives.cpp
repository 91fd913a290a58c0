// Derivatives of the dynamics: d tau/dq, d tau/dalpha by the world-frame passes of
// passes/DynamicsDerivatives.h, and the factors of H that forward_dynamics_derivatives() solves with.
#include <algorithm>
#include <optional>

#include <fmt/format.h>

#include "../passes/DynamicsDerivatives.h"
#include "Functions.h"
#include "Outputs.h"
#include "SceneEffects.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

namespace
{

void emitContactDerivatives(PassContext & ctx, const MotionState & m, const std::vector<WorldBody> & w, const Vec3 & r0,
                            const SceneEffects & fx, std::size_t c);

/// The world frame of the derivative passes: poses (and body velocities when asked), their origin
/// r0 and a_0 = [0; -g].
struct WorldFrame
{
  MotionState m;
  Vec3 r0;
  bool shifted = false;  ///< r0 is not the world origin
  std::vector<Xform> X0; ///< world poses with the origin at r0
  Motion a0;
};

WorldFrame worldFrame(PassContext & ctx, const std::optional<Eigen::Vector3d> & gravity, bool bodyVelocities)
{
  Block & b = ctx.block();
  const RobotModel & rm = ctx.model();
  WorldFrame fr;
  fr.m = forwardMotion(ctx, MotionRequest::make(true, bodyVelocities), ctx.allJoints());
  // Origin of the passes: world axes at the first root joint's body origin r0 (a floating base 1e4 m
  // from the world origin, or an arm mounted 1 km away, would cost ~|r0| u in the moments otherwise);
  // d tau does not depend on the origin. a_0 = [0; -g] is the same at every point.
  fr.r0 = !rm.joints.empty() && rm.joints.front().parent < 0 ? fr.m.X0.front().r : Vec3::zero();
  fr.shifted = !(fr.r0[0].isZero() && fr.r0[1].isZero() && fr.r0[2].isZero());
  fr.X0 = fr.m.X0;
  if(fr.shifted)
    for(std::size_t k = 0; k < rm.joints.size(); ++k) // (the first root joint's is r0 - r0 = 0)
      fr.X0[k].r = k == 0 ? Vec3::zero() : sub(b, fr.m.X0[k].r, fr.r0, rm.joints[k].tag + "_r0");
  fr.a0 = Motion::zero();
  for(int i = 0; i < 3 && gravity; ++i) fr.a0.v[i] = Scalar::constant(-(*gravity)[i]);
  return fr;
}

/// related[col * nv + row]: dofs row and col on one path of the dof tree (one is the other or its
/// ancestor), the entries of d tau/dq and d tau/dalpha that are not structurally zero.
std::vector<bool> onePathEntries(const RobotModel & rm)
{
  const int nv = rm.nv;
  const std::vector<int> lambda = dofParents(rm);
  std::vector<bool> related(static_cast<std::size_t>(nv * nv), false);
  for(int c = 0; c < nv; ++c)
    for(int a = c; a >= 0; a = lambda[static_cast<std::size_t>(a)])
      related[static_cast<std::size_t>(c * nv + a)] = related[static_cast<std::size_t>(a * nv + c)] = true;
  return related;
}

/// One line per run of rows [r0, r1) of column col of out.m set to zero.
void zeroRun(Block & b, const std::string & out, const char * m, int col, int r0, int r1)
{
  if(r1 - r0 == 1) b.line(fmt::format("{}.{}({}, {}) = S(0);", out, m, r0, col));
  else b.line(fmt::format("{}.{}.col({}).template segment<{}>({}).setZero();", out, m, col, r1 - r0, r0));
}

/// Zero into the entries of out.dtau_dq and out.dtau_dalpha off the dof tree's paths (structurally
/// zero), as runs of rows per column; false when there are none (a chain).
bool emitZerosOffPaths(Block & b, const RobotModel & rm, const std::string & out)
{
  const int nv = rm.nv;
  const std::vector<bool> related = onePathEntries(rm);
  if(std::all_of(related.begin(), related.end(), [](bool x) { return x; })) return false;
  const auto off = [&](int row, int col) { return !related[static_cast<std::size_t>(col * nv + row)]; };
  b.comment("the entries off the dof tree's paths: structurally zero");
  for(const char * m : {"dtau_dq", "dtau_dalpha"})
    for(int col = 0; col < nv; ++col)
      for(int r0 = 0, r1 = 0; r0 < nv; r0 = r1)
      {
        for(r1 = r0 + 1; r1 < nv && off(r1, col) == off(r0, col);) ++r1;
        if(off(r0, col)) zeroRun(b, out, m, col, r0, r1);
      }
  return true;
}

/// Up to this many dofs, detail::minus_times_tree2 (templates/detail_opaque.hpp.in) forms -M^-1 dID
/// as two dense products, which read every entry of dID: the forward dynamics derivatives then
/// zero dID's entries off the paths too (a branching tree of 8 dofs or fewer).
constexpr int kDenseProductDofs = 8;

/// The entries of derivativePairs as assignments to out.dtau_dq and out.dtau_dalpha (out: `d` or
/// `id`), then zero into every entry on one path of the dof tree that was not assigned, as runs of
/// rows per column (rather than both matrices zeroed first: a call to memset of 2 nv^2 values, 4 %
/// of solo12's inverse_dynamics_derivatives). The entries off the paths, structurally zero, are left
/// to derivativeZerosOffPaths: -M^-1 dID reads the paths only (talos_reduced + free base: 111 runs
/// of zeros, 2.4-2.8 % of its forward_dynamics_derivatives with clang++ 14, 3-4 % with g++ 12).
void emitDerivativeEntries(PassContext & ctx, const std::vector<WorldBody> & w, const std::vector<SubtreeSums> & c,
                           const std::optional<Eigen::Vector3d> & gravity, const std::vector<Force> & fext, const std::string & out)
{
  Block & b = ctx.block();
  const int nv = ctx.model().nv;
  const char * names[2] = {"dtau_dq", "dtau_dalpha"};
  // set[m][col * nv + row]: entry (row, col) of matrix m assigned
  std::vector<bool> set[2] = {std::vector<bool>(static_cast<std::size_t>(nv * nv)), std::vector<bool>(static_cast<std::size_t>(nv * nv))};
  const auto at = [&](int row, int col) { return static_cast<std::size_t>(col * nv + row); };
  const auto mark = [&](int m, int row, int col) { set[m][at(row, col)] = true; };
  derivativePairs(ctx, w, c, gravity.value_or(Eigen::Vector3d::Zero()), fext,
                  [&](int r, int col, const Scalar & dq, const Scalar & da) {
                    const Scalar * e[2] = {&dq, &da};
                    for(int m = 0; m < 2; ++m)
                      if(!e[m]->isZero())
                      {
                        b.line(fmt::format("{}.{}({}, {}) = {};", out, names[m], r, col, Block::text(*e[m])));
                        mark(m, r, col);
                      }
                  },
                  [&](int col, const BlockEntries & dq, const BlockEntries & da) {
                    const BlockEntries * e[2] = {&dq, &da};
                    for(int m = 0; m < 2; ++m)
                      if(!e[m]->empty())
                      {
                        b.line(e[m]->into(fmt::format("{}.{}.col({})", out, names[m], col)));
                        for(int r = 0; r < e[m]->rows; ++r) mark(m, e[m]->first + r, col);
                      }
                  });
  const std::vector<bool> related = onePathEntries(ctx.model());
  // (an entry off the paths is never assigned: derivativePairs and the contacts' terms are on paths)
  const auto zero = [&](int m, int row, int col) { return !set[m][at(row, col)] && related[at(row, col)]; };
  for(int m = 0; m < 2; ++m)
    for(int col = 0; col < nv; ++col)
      for(int r0 = 0, r1 = 0; r0 < nv; r0 = r1)
      {
        // [r0, r1): a run of rows all to zero or all not
        for(r1 = r0 + 1; r1 < nv && zero(m, r1, col) == zero(m, r0, col);) ++r1;
        if(zero(m, r0, col)) zeroRun(b, out, names[m], col, r0, r1);
      }
}

/// Per joint, the sum over its subtree of the external wrenches `wrenches[w]` on wrenchBodies[w]
/// (world axes at the origin of the passes: n - r0 x f); empty without wrenches.
std::vector<Force> wrenchSums(PassContext & ctx, const WorldFrame & fr, const std::vector<int> & wrenchBodies)
{
  Block & b = ctx.block();
  const RobotModel & rm = ctx.model();
  std::vector<Force> fext;
  if(wrenchBodies.empty()) return fext;
  b.comment("wrench sums over each subtree (world axes at the origin of the passes: n - r0 x f)");
  fext.assign(rm.joints.size(), Force::zero());
  for(std::size_t k = 0; k < wrenchBodies.size(); ++k)
  {
    const int o = rm.bodies[static_cast<std::size_t>(wrenchBodies[k])].owner;
    const std::string slot = fmt::format("wrenches[{}]", k);
    Force wk{vec3Var(slot, 0), vec3Var(slot, 3)};
    if(fr.shifted) wk.n = sub(b, wk.n, cross(b, fr.r0, wk.f, fmt::format("w{}_r0xf", k)), fmt::format("w{}_n0", k));
    for(int a = o; a >= 0; a = rm.joints[static_cast<std::size_t>(a)].parent)
      fext[static_cast<std::size_t>(a)] = cg::add(b, fext[static_cast<std::size_t>(a)], wk, rm.joints[static_cast<std::size_t>(a)].tag + "_Fe");
  }
  return fext;
}

/// The joint-space terms' derivatives into out.dtau_dalpha (out: `d` or `id`): damping alpha,
/// friction alpha / sqrt(alpha^2 + v_s^2) (derivative friction v_s^2 / (.)^(3/2)).
void emitJointSpaceDerivatives(Block & b, const RobotModel & rm, const SceneEffects & fx, const std::string & out)
{
  for(int i = 0; i < rm.nv; ++i)
  {
    const auto ii = static_cast<std::size_t>(i);
    const double damping = ii < fx.damping.size() ? fx.damping[ii] : 0.0;
    const double friction = ii < fx.friction.size() ? fx.friction[ii] : 0.0;
    if(damping == 0.0 && friction == 0.0) continue;
    std::string rhs = damping != 0.0 ? Block::literal(damping) : "";
    if(friction != 0.0)
    {
      const std::string a = fmt::format("alpha[{}]", i), vs2 = Block::literal(fx.frictionVelocity * fx.frictionVelocity);
      b.line(fmt::format("const S fr2_{} = {} * {} + {};", i, a, a, vs2));
      const std::string fr2 = fmt::format("fr2_{}", i);
      rhs += fmt::format("{}{} * {} / ({} * {})", rhs.empty() ? "" : " + ", Block::literal(friction), vs2, fr2, cg::lanesSqrt(fr2));
    }
    b.line(fmt::format("{}.dtau_dalpha({}, {}) += {};", out, i, i, rhs));
  }
}

/// d.dtau_dq and d.dtau_dalpha of the rigid-body terms: gravity (or none), velocity terms (or
/// none), and the world wrenches of the bodies in wrenchBodies read from `wrenches[w]` (held constant).
void emitRigidBodyDerivatives(Block & b, const RobotModel & rm, const std::optional<Eigen::Vector3d> & gravity,
                              bool velocityTerms, const std::vector<int> & wrenchBodies, const SceneEffects * contacts)
{
  PassContext ctx(b, rm);
  const bool anyContact = contacts && !contacts->contacts.empty();
  // poses (and the body velocities the contacts read); the world velocities and accelerations of
  // the rigid-body terms come from worldBodies' own recursion
  const WorldFrame fr = worldFrame(ctx, gravity, anyContact);
  // the rigid-body terms see alpha = 0 without velocity terms; the contacts see the true velocities
  const std::vector<WorldBody> w = worldBodies(ctx, fr.X0, velocityTerms, fr.a0);
  const std::vector<Force> fext = wrenchSums(ctx, fr, wrenchBodies);
  const std::vector<SubtreeSums> c = subtreeSums(ctx, fr.X0, w);
  emitDerivativeEntries(ctx, w, c, gravity, fext, "d");
  if(anyContact)
    for(std::size_t ic = 0; ic < contacts->contacts.size(); ++ic) emitContactDerivatives(ctx, fr.m, w, fr.r0, *contacts, ic);
}

/// - d(J_c^T f_c)/dq and /dalpha of contact c (runtime: SceneDynamics.cpp subtractContactDerivatives,
/// which states the equations): u_j = v_j + w_j x p per dof j on the owner's path (world s_j = [w_j; v_j]),
///   dtau_j/dq_k -= (j after k ? w_k . (u_j x f) : w_j . (u_k x f)) + u_j . (F_p u_k + F_v dpdot_k)
///   dpdot_k = w_k x V_k + W_k x u_k,  dtau_j/dalpha_k -= u_j . F_v u_k.
void emitContactDerivatives(PassContext & ctx, const MotionState & m, const std::vector<WorldBody> & w, const Vec3 & r0,
                            const SceneEffects & fx, std::size_t c)
{
  Block & b = ctx.block();
  const RobotModel & rm = ctx.model();
  const SceneContact & sc = fx.contacts[c];
  const int o = rm.bodies[static_cast<std::size_t>(sc.body)].owner;
  if(o < 0) return; // a point of a static body: no dependence on q or alpha
  const auto ko = static_cast<std::size_t>(o);
  const std::string h = fmt::format("dc{}", c);
  b.comment(fmt::format("contact '{}': d(J_c^T f_c) (F_p = df/dp, F_v = df/dpdot where the point is pushed)", sc.name));
  Vec3 pos, vel;
  emitPointMotion(b, m.X0[ko], m.v[ko], contactPointInOwner(rm, sc), pos, vel, h);
  const Vec3 f = emitContactForce(b, fx, pos, vel, h);
  const Vec3 p0 = sub(b, pos, r0, h + "_p0"); // the point from the origin of the passes
  // fn = k depth - c pdot_z, ft = -mu fn vt / r: F_p = [0 0 Fpz], F_v below (zero when not pushed)
  const std::string fn = Block::text(f[2]), on = h + "_on";
  b.line(fmt::format("const S {} = {};", on, cg::lanesSelect(fn + " > S(0)", "S(1)", "S(0)")));
  Vec3 Fpz = Vec3::zero();
  Mat3 Fv;
  for(int i = 0; i < 9; ++i) Fv.m[static_cast<std::size_t>(i)] = Scalar::constant(0.0);
  Fpz[2] = b.def(fmt::format("{} * {}", Block::literal(-fx.stiffness), on), h + "_Fpz");
  Fv(2, 2) = b.def(fmt::format("{} * {}", Block::literal(-fx.contactDamping), on), h + "_Fv22");
  if(fx.mu != 0.0)
  {
    const std::string r = b.def(cg::lanesSqrt(Block::text(b.sum({Term{1.0, {vel[0], vel[0]}}, Term{1.0, {vel[1], vel[1]}},
                                                                          Term{fx.slipVelocity * fx.slipVelocity, {}}}, h + "_r2"))),
                                h + "_r").name();
    const std::string vx = Block::text(vel[0]), vy = Block::text(vel[1]);
    const std::string g = b.def(fmt::format("{} * {} / {}", Block::literal(fx.mu), fn, r), h + "_g").name();        // mu fn / r
    const std::string g3 = b.def(fmt::format("{} / ({} * {})", g, r, r), h + "_g3").name();                       // mu fn / r^3
    const std::string kr = b.def(fmt::format("{} * {} / {}", Block::literal(fx.mu * fx.stiffness), on, r), h + "_kr").name(); // mu k / r
    const std::string cr = b.def(fmt::format("{} * {} / {}", Block::literal(fx.mu * fx.contactDamping), on, r), h + "_cr").name();
    Fpz[0] = b.def(fmt::format("{} * {}", kr, vx), h + "_Fpx");
    Fpz[1] = b.def(fmt::format("{} * {}", kr, vy), h + "_Fpy");
    Fv(0, 0) = b.def(fmt::format("{} * {} * {} - {}", g3, vx, vx, g), h + "_Fv00");
    Fv(1, 1) = b.def(fmt::format("{} * {} * {} - {}", g3, vy, vy, g), h + "_Fv11");
    Fv(0, 1) = Fv(1, 0) = b.def(fmt::format("{} * {} * {}", g3, vx, vy), h + "_Fv01");
    Fv(0, 2) = b.def(fmt::format("{} * {}", cr, vx), h + "_Fv02");
    Fv(1, 2) = b.def(fmt::format("{} * {}", cr, vy), h + "_Fv12");
  }
  // the dofs on the path: world [w_j; u_j] at the point, their joint's position on the path
  struct Col
  {
    int dof, pos;
    Vec3 w, u;
  };
  std::vector<Col> cols;
  const std::vector<int> path = rm.path(o);
  for(std::size_t pj = 0; pj < path.size(); ++pj)
  {
    const auto j = static_cast<std::size_t>(path[pj]);
    for(std::size_t d = 0; d < w[j].s.size(); ++d)
    {
      const Motion & s = w[j].s[d];
      const int dof = rm.joints[j].vIndex + static_cast<int>(d);
      cols.push_back({dof, static_cast<int>(pj), s.w, add(b, s.v, cross(b, s.w, p0, fmt::format("{}_wp{}", h, dof)), fmt::format("{}_u{}", h, dof))});
    }
  }
  // V_J = sum over the dofs at and after joint J of alpha u, W_J = sum before J of alpha w
  std::vector<Vec3> V(path.size(), Vec3::zero()), W(path.size(), Vec3::zero());
  for(std::size_t pj = path.size(); pj-- > 0;)
  {
    if(pj + 1 < path.size()) V[pj] = V[pj + 1];
    for(const Col & cl : cols)
      if(cl.pos == static_cast<int>(pj))
        V[pj] = add(b, V[pj], scale(b, Scalar::var(fmt::format("alpha[{}]", cl.dof)), cl.u, fmt::format("{}_au{}", h, cl.dof)), fmt::format("{}_V{}", h, pj));
  }
  for(std::size_t pj = 1; pj < path.size(); ++pj)
  {
    W[pj] = W[pj - 1];
    for(const Col & cl : cols)
      if(cl.pos == static_cast<int>(pj) - 1)
        W[pj] = add(b, W[pj], scale(b, Scalar::var(fmt::format("alpha[{}]", cl.dof)), cl.w, fmt::format("{}_aw{}", h, cl.dof)), fmt::format("{}_W{}", h, pj));
  }
  std::vector<Vec3> df, FvU, t;
  for(const Col & k : cols)
  {
    const auto pk = static_cast<std::size_t>(k.pos);
    const Vec3 dpd = add(b, cross(b, k.w, V[pk], fmt::format("{}_wV{}", h, k.dof)), cross(b, W[pk], k.u, fmt::format("{}_Wu{}", h, k.dof)),
                         fmt::format("{}_dpd{}", h, k.dof));
    FvU.push_back(mul(b, Fv, k.u, fmt::format("{}_FvU{}", h, k.dof)));
    df.push_back(add(b, scale(b, k.u[2], Fpz, fmt::format("{}_Fpu{}", h, k.dof)), mul(b, Fv, dpd, fmt::format("{}_Fvd{}", h, k.dof)),
                     fmt::format("{}_df{}", h, k.dof)));
    t.push_back(cross(b, k.u, f, fmt::format("{}_t{}", h, k.dof)));
  }
  auto dotTerms = [](std::vector<Term> & terms, const Vec3 & x, const Vec3 & y) {
    for(int i = 0; i < 3; ++i) terms.push_back(Term{1.0, {x[i], y[i]}});
  };
  for(std::size_t jj = 0; jj < cols.size(); ++jj)
    for(std::size_t kk = 0; kk < cols.size(); ++kk)
    {
      const Col & j = cols[jj];
      const Col & k = cols[kk];
      std::vector<Term> dq, da;
      if(j.pos >= k.pos) dotTerms(dq, k.w, t[jj]);
      else dotTerms(dq, j.w, t[kk]);
      dotTerms(dq, j.u, df[kk]);
      dotTerms(da, j.u, FvU[kk]);
      b.line(fmt::format("d.dtau_dq({}, {}) -= {};", j.dof, k.dof, Block::text(dq)));
      b.line(fmt::format("d.dtau_dalpha({}, {}) -= {};", j.dof, k.dof, Block::text(da)));
    }
}

/// A floating base whose columns of the forward dynamics derivatives have a closed form
/// (emitFloatingBaseColumns): a root free joint (forward), no contacts and no wrenches (anchored in
/// the world), no armature on its linear dofs (H's columns of those dofs are then the derivatives of
/// tau with respect to the base's acceleration); its linear velocity columns too when those dofs have
/// no damping and no friction either.
struct FloatingBase
{
  int joint = 0;
  bool velocityColumns = false;
};

std::vector<FloatingBase> floatingBases(const RobotModel & rm, const SceneEffects & fx)
{
  std::vector<FloatingBase> roots;
  if(!fx.contacts.empty() || !fx.wrenchBodies.empty()) return roots;
  const auto nonZero = [](const std::vector<double> & v, std::size_t i) { return i < v.size() && v[i] != 0.0; };
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    if(mj.parent >= 0 || mj.joint.type() != rbd::Joint::Free || !mj.joint.forward()) continue;
    bool armature = false, jointSpace = false;
    for(int d = 3; d < 6; ++d)
    {
      const auto i = static_cast<std::size_t>(mj.vIndex + d);
      armature = armature || nonZero(fx.armature, i);
      jointSpace = jointSpace || nonZero(fx.damping, i) || nonZero(fx.friction, i);
    }
    if(!armature) roots.push_back({static_cast<int>(k), !jointSpace});
  }
  return roots;
}

/// -[x]x(r, c) as a term of out(row0 + r, col0 + c) for r != c: -eps(r, i, c) x_i = (0, 1) x_z,
/// (0, 2) -x_y, (1, 0) -x_z, (1, 2) x_x, (2, 0) x_y, (2, 1) -x_x.
void emitMinusCross(Block & b, const std::string & out, int row0, int col0, const Vec3 & x)
{
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c)
    {
      const int i = 3 - r - c;
      if(r == c || x[i].isZero()) continue;
      const double sign = (c - r + 3) % 3 == 1 ? 1.0 : -1.0;
      b.line(fmt::format("{}({}, {}) = {};", out, row0 + r, col0 + c, Block::text({Term{sign, {x[i]}}})));
    }
}

/// A floating base's columns of d alphaD/dq and d alphaD/dalpha in closed form (floatingBases; E:
/// world to its body frame). tau(q, alpha, alphaD) = tau_0(q', alpha, alphaD + [0; gamma]), gamma
/// = E g_up the world's upward gravity acceleration in the base frame and q' the other joints'
/// coordinates: a step [dw; dv] of the base's pose (base frame) turns gamma by gamma x dw and moves
/// tau no other way, so dID/dq over its dofs is [H(:, lin) [gamma]x, 0] and -H^-1 dID is
/// -I(:, lin) [gamma]x. A base velocity step dv adds a uniform velocity (Galilean: no force) but,
/// alphaD held, a base acceleration w x dv: dID/dalpha_lin = H(:, lin) [w]x with w the base's angular
/// velocity, and d alphaD/dalpha_lin = -I(:, lin) [w]x (a single body: v' = f/m - w x v). Exact,
/// where -H^-1 dID sums products that cancel to it (of the 1,400 entries of dID the two products
/// read on talos_reduced, 342).
void emitFloatingBaseColumns(Block & b, const MovingJoint & mj, const FloatingBase & fb, const Mat3 & E,
                             const std::optional<Eigen::Vector3d> & gravity, bool velocityTerms)
{
  const int o = mj.vIndex;
  b.comment(fmt::format("joint '{}' (dofs {}-{}): d alphaD/dq = -[gamma]x in rows {}-{} of columns {}-{} (gamma = E g_up){}, "
                        "zero elsewhere",
                        mj.name, o, o + 5, o + 3, o + 5, o, o + 2,
                        fb.velocityColumns ? fmt::format("; d alphaD/dalpha = -[w]x in rows {}-{} of columns {}-{} (w = alpha[{}-{}])",
                                                         o + 3, o + 5, o + 3, o + 5, o, o + 2)
                                           : ""));
  b.line(fmt::format("d.dalphaD_dq.template middleCols<6>({}).setZero();", o));
  if(gravity) emitMinusCross(b, "d.dalphaD_dq", o + 3, o, mul(b, E, Vec3::constant(-*gravity), mj.tag + "_gup"));
  if(!fb.velocityColumns) return;
  b.line(fmt::format("d.dalphaD_dalpha.template middleCols<3>({}).setZero();", o + 3));
  if(velocityTerms)
  {
    Vec3 w;
    for(int i = 0; i < 3; ++i) w[i] = Scalar::var(fmt::format("alpha[{}]", o + i));
    emitMinusCross(b, "d.dalphaD_dalpha", o + 3, o + 3, w);
  }
}

/// Minv = H^-1 = W^T D^-1 W (W = L^-T, from the factors), then d alphaD = -Minv dID. Row j of W is
/// non-zero only in the columns of j's subtree [j, end_j]: the row operations of W use that segment,
/// and every row of Minv sums such segments in registers (detail::row_from_segments: pieces of 8
/// values, only those a segment overlaps). The rows are those of d.Minv's storage read as row-major
/// (M^-1 is symmetric: no copy). dID's column c is zero but in the rows of c's ancestors and subtree (a
/// torque depends on the q and alpha of the joints on its own paths only), so each column of the
/// product sums those rows of Minv only (detail::minus_times_tree2): talos_reduced + free base
/// 700 of 1,444 entries.
/// The columns of the floating bases (E: world to body, emitFloatingBaseColumns) are not part of the
/// products.
void emitDerivativeSolves(Block & b, const Ltdl & f, std::size_t nv, const RobotModel & rm, const SceneEffects & fx,
                          const std::vector<std::pair<FloatingBase, Mat3>> & bases)
{
  std::vector<std::size_t> end(nv);
  for(std::size_t i = 0; i < nv; ++i) end[i] = i;
  for(std::size_t k = nv; k-- > 0;)
    for(int j = f.lambda[k]; j >= 0; j = f.lambda[static_cast<std::size_t>(j)])
      end[static_cast<std::size_t>(j)] = std::max(end[static_cast<std::size_t>(j)], end[k]);
  // M^-1 = L^-1 D^-1 L^-T = W^T D^-1 W with W = L^-T, whose row j is non-zero over j's subtree
  // [j, end(j)] only. W by row operations on the identity (L^T pass, leaves first: row j -= L(i, j)
  // row i over the segment [i, end(i)] of row i, for each ancestor j of i), then each row of M^-1 in
  // registers from segments (detail::row_from_segments), rows from the last up, so that every row
  // read is still W's:   M^-1(a, :) = sum over a's ancestors k and a itself of (W(k, a) / D_k) W(k, :)
  const auto rowCall = [&](std::size_t row, const std::vector<std::size_t> & from, const std::vector<std::string> & coef) {
    std::string bounds, rows, cs;
    for(std::size_t t = 0; t < from.size(); ++t)
    {
      bounds += fmt::format(", {}, {}", from[t], end[from[t]] + 1);
      rows += fmt::format("{}X + {}", t ? ", " : "", from[t] * nv);
      cs += (t ? ", " : "") + coef[t];
    }
    return fmt::format("detail::row_from_segments<nv{}>(X + {}, {{{}}}, {{{}}});", bounds, row * nv, cs, rows);
  };
  b.comment("Minv = H^-1 = W^T D^-1 W, W = L^-T: W by row operations on the identity, then the rows of Minv (from the last), "
            "X row-major");
  // X = 1 as zeros then the diagonal: Identity() fills entry by entry with a test per entry
  // (talos_reduced: 3.9 % of forward_dynamics_derivatives, against 0.3 % more in memset this way)
  b.line("d.Minv.setZero();");
  b.line("d.Minv.diagonal().setOnes();");
  b.line("S * const X = d.Minv.data();");
  for(std::size_t i = nv; i-- > 0;)
    for(int j = f.lambda[i]; j >= 0; j = f.lambda[static_cast<std::size_t>(j)])
      if(const Scalar & l = f.L[i][static_cast<std::size_t>(j)]; !l.isZero())
        b.line(fmt::format("detail::row_axpy<{}>(X + {}, {}, X + {});", end[i] - i + 1, static_cast<std::size_t>(j) * nv + i, Block::text(l),
                           i * nv + i));
  for(std::size_t a = nv; a-- > 0;)
  {
    std::vector<std::size_t> from = f.ancestorsRootFirst(a);
    std::vector<std::string> coef;
    for(const std::size_t k : from) coef.push_back(fmt::format("X[{}] * {}", k * nv + a, Block::text(f.invD[k])));
    from.push_back(a);
    coef.push_back(Block::text(f.invD[a]));
    b.line(rowCall(a, from, coef));
  }
  std::string parents, ends;
  for(std::size_t i = 0; i < nv; ++i)
  {
    parents += fmt::format("{}{}", i ? ", " : "", f.lambda[i]);
    ends += fmt::format("{}{}", i ? ", " : "", end[i]);
  }
  b.comment("d alphaD = -H^-1 dID at alphaD (dof tree: parent and last dof of the subtree of each dof)");
  b.line(fmt::format("static constexpr int dof_parent[nv] = {{{}}}, subtree_end[nv] = {{{}}};", parents, ends));
  if(bases.empty())
  {
    b.line("detail::minus_times_tree2<S, nv>(d.dalphaD_dq, d.dalphaD_dalpha, d.Minv, id.dtau_dq, id.dtau_dalpha, dof_parent, subtree_end);");
    return;
  }
  std::vector<bool> closedQ(nv, false), closedA(nv, false);
  for(const auto & [fb, E] : bases)
  {
    const auto o = static_cast<std::size_t>(rm.joints[static_cast<std::size_t>(fb.joint)].vIndex);
    for(std::size_t d = 0; d < 6; ++d) closedQ[o + d] = true;
    for(std::size_t d = 3; d < 6 && fb.velocityColumns; ++d) closedA[o + d] = true;
  }
  const auto flags = [nv](const std::vector<bool> & v) {
    std::string s;
    for(std::size_t i = 0; i < nv; ++i) s += fmt::format("{}{}", i ? ", " : "", v[i] ? "true" : "false");
    return s;
  };
  b.line(fmt::format("static constexpr bool dq_closed[nv] = {{{}}}, dalpha_closed[nv] = {{{}}};", flags(closedQ), flags(closedA)));
  b.line("detail::minus_times_tree2<S, nv>(d.dalphaD_dq, d.dalphaD_dalpha, d.Minv, id.dtau_dq, id.dtau_dalpha, dof_parent, subtree_end, "
         "dq_closed, dalpha_closed);");
  for(const auto & [fb, E] : bases)
    emitFloatingBaseColumns(b, rm.joints[static_cast<std::size_t>(fb.joint)], fb, E, fx.gravity, fx.velocityTerms);
}

/// alphaD = (H + diag(armature))^-1 (tau - bias) into d.alphaD, then the derivatives (biasCall
/// empty: no bias; idCall: the statement filling `id`, the ID derivatives at d.alphaD on the dof
/// tree's paths).
EmittedBody fdDerivativesBody(const RobotModel & rm, const SceneEffects & fx, const std::string & biasCall, const std::string & idCall)
{
  Block b;
  const auto nv = static_cast<std::size_t>(rm.nv);
  if(!biasCall.empty()) b.line("const Tangent<S> C = " + biasCall + ";");
  const Ltdl f = emitLtdl(b, rm, emitMassMatrix(b, rm, fx.armature));
  std::vector<Scalar> x(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    const Scalar tau = Scalar::var(fmt::format("tau[{}]", i));
    x[i] = biasCall.empty() ? tau : b.sum({Term{1.0, {tau}}, Term{-1.0, {Scalar::var(fmt::format("C[{}]", i))}}}, fmt::format("x{}", i));
  }
  x = emitLtdlSolve(b, f, std::move(x));
  for(std::size_t i = 0; i < nv; ++i) b.line(fmt::format("d.alphaD[{}] = {};", i, Block::text(x[i])));
  b.line("IdDerivatives<S> id;");
  b.line(idCall + ";");
  if(rm.nv <= kDenseProductDofs) emitZerosOffPaths(b, rm, "id");
  std::vector<std::pair<FloatingBase, Mat3>> bases;
  for(const FloatingBase & fb : floatingBases(rm, fx)) // E = E_j(q) E_T: the joint's kernel, its fixed transform from the world
  {
    const MovingJoint & mj = rm.joints[static_cast<std::size_t>(fb.joint)];
    bases.emplace_back(fb, compose(b, emitJointKernel(b, mj, "q").Xj, treeXform(mj), mj.tag + "_X0").E);
  }
  emitDerivativeSolves(b, f, nv, rm, fx, bases);
  return finish(b);
}

/// tau_k minus the bias of dof k (velocity sk) at alphaD = 0: s_k . (Gc - Fext) (fext: nullptr when
/// none), damping alpha_k, friction alpha_k / sqrt(alpha_k^2 + v_s^2) as the scene's RNEA has them.
std::vector<Term> biasTerms(Block & b, const SceneEffects & fx, std::size_t k, const Motion & sk, const Force & Gc, const Force * fext)
{
  const std::string al = fmt::format("alpha[{}]", k);
  std::vector<Term> t{Term{1.0, {Scalar::var(fmt::format("tau[{}]", k))}}, Term{-1.0, {dot(b, sk, Gc, fmt::format("C{}", k))}}};
  if(fext) t.push_back(Term{1.0, {dot(b, sk, *fext, fmt::format("Ce{}", k))}});
  if(k < fx.damping.size() && fx.damping[k] != 0.0) t.push_back(Term{-fx.damping[k], {Scalar::var(al)}});
  if(k < fx.friction.size() && fx.friction[k] != 0.0)
    t.push_back(Term{-1.0, {b.def(fmt::format("{} * {} / {}", Block::literal(fx.friction[k]), al,
                                              cg::lanesSqrt(fmt::format("{} * {} + {}", al, al, Block::literal(fx.frictionVelocity * fx.frictionVelocity)))),
                                  fmt::format("fr{}", k))}});
  return t;
}

/// forward_dynamics_derivatives in one body, the kinematics computed once (without contacts: those
/// scenes call their bias and ID derivatives): the world passes of the ID derivatives at alphaD = 0
/// give the bias, tau_k = s_k . (Gc_i - Fext_i) for dof k of joint i (+ the joint-space terms), and
/// H(k, m) = s_m . Ic_i s_k for the dofs m on k's path (the CRBA in world
/// coordinates). After the solve, the accelerations and the subtree forces, linear in alphaD, move
/// by Da_k = Da_p + sum s alphaD over joint k's dofs and
///   DGc_i = sum over i's subtree of I_b Da_b = Ic_i Da_p(i) + sum over the dofs m of i's subtree
///           of (Ic_j(m) s_m) alphaD_m,
/// then the derivative pairs at (q, alpha, alphaD) and -H^-1 dID as in fdDerivativesBody.
EmittedBody fusedFdDerivativesBody(const RobotModel & rm, const SceneEffects & fx)
{
  Block b;
  PassContext ctx(b, rm);
  const auto nv = static_cast<std::size_t>(rm.nv);
  const std::size_t n = rm.joints.size();
  const WorldFrame fr = worldFrame(ctx, fx.gravity, false);
  std::vector<WorldBody> w = worldBodies(ctx, fr.X0, fx.velocityTerms, fr.a0, false);
  const std::vector<Force> fext = wrenchSums(ctx, fr, fx.wrenchBodies);
  std::vector<SubtreeSums> c = subtreeSums(ctx, fr.X0, w);
  b.comment(fmt::format("H(k, m) = s_m . Ic_i s_k for the dofs m on the path of dof k (joint i); tau - bias, bias_k = s_k . {} at "
                        "alphaD = 0{}",
                        fext.empty() ? "Gc_i" : "(Gc_i - Fext_i)", fx.hasDamping() || fx.hasFriction() ? " + the joint-space terms" : ""));
  std::vector<std::vector<Scalar>> H(nv, std::vector<Scalar>(nv));
  std::vector<Force> u(nv); // Ic_i s_k
  std::vector<Scalar> x(nv);
  for(std::size_t i = 0; i < n; ++i)
  {
    const MovingJoint & mj = rm.joints[i];
    for(std::size_t d = 0; d < w[i].s.size(); ++d)
    {
      const auto k = static_cast<std::size_t>(mj.vIndex) + d;
      u[k] = cg::apply(b, c[i].Ic, w[i].s[d], fmt::format("{}_{}Hu", mj.tag, d));
      x[k] = b.sum(biasTerms(b, fx, k, w[i].s[d], c[i].Gc, fext.empty() ? nullptr : &fext[i]), fmt::format("x{}", k));
      const auto entry = [&](const Motion & sm, std::size_t m) { H[k][m] = dot(b, sm, u[k], fmt::format("H{}_{}", k, m)); };
      for(std::size_t e = 0; e <= d; ++e) entry(w[i].s[e], static_cast<std::size_t>(mj.vIndex) + e);
      for(int a = mj.parent; a >= 0; a = rm.joints[static_cast<std::size_t>(a)].parent)
      {
        const auto ak = static_cast<std::size_t>(a);
        for(std::size_t e = 0; e < w[ak].s.size(); ++e) entry(w[ak].s[e], static_cast<std::size_t>(rm.joints[ak].vIndex) + e);
      }
      if(k < fx.armature.size() && fx.armature[k] != 0.0)
        H[k][k] = b.sum({Term{1.0, {H[k][k]}}, Term{fx.armature[k], {}}}, fmt::format("Ha{}", k));
    }
  }
  const Ltdl f = emitLtdl(b, rm, std::move(H));
  x = emitLtdlSolve(b, f, std::move(x));
  for(std::size_t k = 0; k < nv; ++k) b.line(fmt::format("d.alphaD[{}] = {};", k, Block::text(x[k])));
  b.comment("the world accelerations and subtree forces at alphaD: a_k += Da_k, Gc_i += DGc_i");
  std::vector<Motion> da(n);
  for(std::size_t i = 0; i < n; ++i) // (parents first)
  {
    const MovingJoint & mj = rm.joints[i];
    Motion aJ = Motion::zero();
    for(std::size_t d = 0; d < w[i].s.size(); ++d)
    {
      const Scalar & a = x[static_cast<std::size_t>(mj.vIndex) + d];
      const std::string h = fmt::format("{}_{}Das", mj.tag, d);
      aJ = cg::add(b, aJ, Motion{cg::scale(b, a, w[i].s[d].w, h + "w"), cg::scale(b, a, w[i].s[d].v, h + "v")}, mj.tag + "_DaJ");
    }
    da[i] = mj.parent < 0 ? aJ : add(b, da[static_cast<std::size_t>(mj.parent)], aJ, mj.tag + "_Da");
    w[i].a = add(b, w[i].a, da[i], mj.tag + "_awD");
  }
  std::vector<Force> Y(n, Force::zero()); // sum over the dofs m of the subtree of (Ic s_m) alphaD_m
  for(std::size_t i = n; i-- > 0;) // (children first)
  {
    const MovingJoint & mj = rm.joints[i];
    for(std::size_t d = 0; d < w[i].s.size(); ++d)
    {
      const auto k = static_cast<std::size_t>(mj.vIndex) + d;
      Y[i] = cg::add(b, Y[i], Force{cg::scale(b, x[k], u[k].n, fmt::format("{}_{}Yn", mj.tag, d)),
                                    cg::scale(b, x[k], u[k].f, fmt::format("{}_{}Yf", mj.tag, d))},
                     mj.tag + "_Y");
    }
    if(mj.parent < 0)
    {
      c[i].Gc = cg::add(b, c[i].Gc, Y[i], mj.tag + "_GcD");
      continue;
    }
    const auto p = static_cast<std::size_t>(mj.parent);
    const Force dG = cg::add(b, cg::apply(b, c[i].Ic, da[p], mj.tag + "_IDa"), Y[i], mj.tag + "_DG");
    c[i].Gc = cg::add(b, c[i].Gc, dG, mj.tag + "_GcD");
    Y[p] = cg::add(b, Y[p], Y[i], rm.joints[p].tag + "_Y");
  }
  b.line("IdDerivatives<S> id;");
  emitDerivativeEntries(ctx, w, c, fx.gravity, fext, "id");
  if(rm.nv <= kDenseProductDofs) emitZerosOffPaths(b, rm, "id");
  emitJointSpaceDerivatives(b, rm, fx, "id");
  std::vector<std::pair<FloatingBase, Mat3>> bases;
  for(const FloatingBase & fb : floatingBases(rm, fx)) bases.emplace_back(fb, fr.X0[static_cast<std::size_t>(fb.joint)].E);
  emitDerivativeSolves(b, f, nv, rm, fx, bases);
  return finish(b);
}

} // namespace

std::string derivativeZerosOffPaths(const RobotModel & rm)
{
  Block b;
  return emitZerosOffPaths(b, rm, "d") ? finish(b).text : "";
}

EmittedBody inverseDynamicsDerivativesBody(const RobotModel & rm, const SceneEffects & fx)
{
  Block b;
  emitRigidBodyDerivatives(b, rm, fx.gravity, fx.velocityTerms, fx.wrenchBodies, &fx);
  emitJointSpaceDerivatives(b, rm, fx, "d");
  return finish(b);
}

EmittedBody forwardDynamicsDerivativesBody(const RobotModel & rm, const SceneEffects & fx, const std::string & biasCall,
                                            const std::string & wrenchArg)
{
  if(fx.contacts.empty() && !derivativesInArrays(rm))
    return fusedFdDerivativesBody(rm, fx);
  return fdDerivativesBody(rm, fx, biasCall,
                           "detail::inverse_dynamics_derivatives_on_paths<S>(q, alpha, d.alphaD" + wrenchArg + ", id)");
}

} // namespace rbdgen::emit
