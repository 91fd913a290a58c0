#include "DynamicsDerivatives.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "BackwardForce.h"

namespace rbdgen::passes
{

namespace
{

/// m . f = w . n + v . f
Scalar dot(Block & b, const Motion & m, const Force & f, const std::string & hint)
{
  std::vector<Term> t;
  for(int i = 0; i < 3; ++i)
  {
    t.push_back(Term{1.0, {m.w[i], f.n[i]}});
    t.push_back(Term{1.0, {m.v[i], f.f[i]}});
  }
  return b.sum(t, hint);
}

/// dI/dt x = [J w + hd x v; -hd x w]
Force apply(Block & b, const InertiaRate & R, const Motion & x, const std::string & hint)
{
  Force o;
  for(int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    o.n[i] = b.sum({Term{1.0, {R.J(i, 0), x.w[0]}}, Term{1.0, {R.J(i, 1), x.w[1]}}, Term{1.0, {R.J(i, 2), x.w[2]}},
                    Term{1.0, {R.hd[j], x.v[k]}}, Term{-1.0, {R.hd[k], x.v[j]}}},
                   fmt::format("{}_n{}", hint, i));
    o.f[i] = b.sum({Term{-1.0, {R.hd[j], x.w[k]}}, Term{1.0, {R.hd[k], x.w[j]}}}, fmt::format("{}_f{}", hint, i));
  }
  return o;
}

/// dI/dt of the world inertia I moving with the world twist v = [w; u].
InertiaRate inertiaRate(Block & b, const Inertia & I, const Motion & v, const std::string & hint)
{
  InertiaRate R;
  const Scalar vh = cg::dot(b, v.v, I.h, hint + "_vh");
  // J = A + A^T - h u^T - u h^T + 2 (u.h) 1,  A(r, c) = (w x Ibar_c)_r
  auto A = [&](int r, int c, double sign) {
    const int j = (r + 1) % 3, k = (r + 2) % 3;
    return std::vector<Term>{Term{sign, {v.w[j], I.I(k, c)}}, Term{-sign, {v.w[k], I.I(j, c)}}};
  };
  for(int r = 0; r < 3; ++r)
    for(int c = r; c < 3; ++c)
    {
      std::vector<Term> t = A(r, c, 1.0);
      for(Term & x : A(c, r, 1.0)) t.push_back(x);
      t.push_back(Term{-1.0, {I.h[r], v.v[c]}});
      t.push_back(Term{-1.0, {v.v[r], I.h[c]}});
      if(r == c) t.push_back(Term{2.0, {vh}});
      R.J(r, c) = b.sum(t, fmt::format("{}_J{}{}", hint, r, c));
      R.J(c, r) = R.J(r, c);
    }
  // hd = w x h + m u
  for(int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    R.hd[i] = b.sum({Term{1.0, {v.w[j], I.h[k]}}, Term{-1.0, {v.w[k], I.h[j]}}, Term{1.0, {I.m, v.v[i]}}},
                    fmt::format("{}_hd{}", hint, i));
  }
  return R;
}

InertiaRate add(Block & b, const InertiaRate & x, const InertiaRate & y, const std::string & hint)
{
  return {addSym(b, x.J, y.J, hint + "_J"), cg::add(b, x.hd, y.hd, hint + "_hd")};
}

Motion zeroMotion() { return Motion::zero(); }

} // namespace

std::vector<WorldBody> worldBodies(PassContext & ctx, const MotionState & m)
{
  Block & b = ctx.block();
  std::vector<WorldBody> out(ctx.model().joints.size());
  for(int k : ctx.allJoints())
  {
    const auto kk = static_cast<std::size_t>(k);
    const MovingJoint & mj = ctx.joint(k);
    const JointKernel & K = ctx.kernel(k);
    const Xform & X0 = m.X0[kk];
    WorldBody & w = out[kk];
    b.comment(fmt::format("{}: world s, v, a, I, I v, I a + v x* I v, dI/dt", mj.tag));
    for(std::size_t d = 0; d < K.S.size(); ++d) w.s.push_back(invApply(b, X0, K.S[d], fmt::format("{}_s{}", mj.tag, d)));
    w.v = invApply(b, X0, m.v[kk], mj.tag + "_vw");
    w.a = invApply(b, X0, m.a[kk], mj.tag + "_aw");
    w.I = transApply(b, X0, bodyInertia(mj), mj.tag + "_Iw");
    w.h = cg::apply(b, w.I, w.v, mj.tag + "_hw");
    w.g = cg::add(b, cg::apply(b, w.I, w.a, mj.tag + "_Ia"), crossDual(b, w.v, w.h, mj.tag + "_vxh"), mj.tag + "_gw");
    w.Id = inertiaRate(b, w.I, w.v, mj.tag + "_Id");
  }
  return out;
}

std::vector<SubtreeSums> subtreeSums(PassContext & ctx, const std::vector<WorldBody> & w)
{
  Block & b = ctx.block();
  const RobotModel & rm = ctx.model();
  std::vector<SubtreeSums> c(rm.joints.size());
  for(std::size_t k = 0; k < rm.joints.size(); ++k) c[k] = {w[k].I, w[k].Id, w[k].h, w[k].g};
  b.comment("subtree sums (world): Ic, dIc/dt, momentum, inertial force");
  for(std::size_t k = rm.joints.size(); k-- > 0;)
  {
    const int p = rm.joints[k].parent;
    if(p < 0) continue;
    const auto pk = static_cast<std::size_t>(p);
    const std::string h = rm.joints[pk].tag + "c";
    c[pk].Ic = cg::add(b, c[pk].Ic, c[k].Ic, h + "_I");
    c[pk].Idc = add(b, c[pk].Idc, c[k].Idc, h + "_Id");
    c[pk].Hc = cg::add(b, c[pk].Hc, c[k].Hc, h + "_H");
    c[pk].Gc = cg::add(b, c[pk].Gc, c[k].Gc, h + "_G");
  }
  return c;
}

/// From this many dofs on, the pairs' long-lived inputs go through arrays (detail::opaque) and each
/// column is an out-of-line lambda: g++ -O2 on talos_reduced (38 dofs): 85 s -> 44 s (arrays) -> 26 s
/// (columns; 66 s on the same day without them) for inverse_dynamics_derivatives, as fast at run time
/// (8.3-9.0 us vs 9.6-9.9 us); below it the registers win (ur5e: 650 ns in registers, 1,350 ns
/// through the arrays).
constexpr int kStashDofs = 24;

/// Stores the non-constant scalars in array[k][0..] and replaces them by those slots.
void stashScalars(Block & b, const std::string & array, int k, const std::vector<Scalar *> & e)
{
  for(std::size_t i = 0; i < e.size(); ++i)
  {
    if(e[i]->isConst()) continue;
    const std::string slot = fmt::format("{}[{}][{}]", array, k, i);
    b.line(fmt::format("{} = {};", slot, Block::text(*e[i])));
    *e[i] = Scalar::var(slot);
  }
}

/// The world quantities of every joint the pairs read (v, a, composite sums), kept in an array.
struct PairJoint
{
  Motion v, a;
  SubtreeSums c;
};

std::vector<PairJoint> stashJoints(Block & b, const std::vector<WorldBody> & w, const std::vector<SubtreeSums> & c, bool stash)
{
  std::vector<PairJoint> out(w.size());
  for(std::size_t k = 0; k < w.size(); ++k) out[k] = PairJoint{w[k].v, w[k].a, c[k]};
  if(!stash) return out;
  b.line(fmt::format("S pair_j[{}][43];", std::max<std::size_t>(w.size(), 1)));
  for(std::size_t k = 0; k < w.size(); ++k)
  {
    PairJoint & p = out[k];
    std::vector<Scalar *> e;
    for(Vec3 * x : {&p.v.w, &p.v.v, &p.a.w, &p.a.v, &p.c.Ic.h, &p.c.Idc.hd, &p.c.Hc.n, &p.c.Hc.f, &p.c.Gc.n, &p.c.Gc.f})
      for(int i = 0; i < 3; ++i) e.push_back(&(*x)[i]);
    e.push_back(&p.c.Ic.m);
    // symmetric 3x3: the upper triangle, the lower one mirrors it
    for(Mat3 * M : {&p.c.Ic.I, &p.c.Idc.J})
      for(int r = 0; r < 3; ++r)
        for(int col = r; col < 3; ++col) e.push_back(&(*M)(r, col));
    stashScalars(b, "pair_j", static_cast<int>(k), e);
    for(Mat3 * M : {&p.c.Ic.I, &p.c.Idc.J})
      for(int r = 0; r < 3; ++r)
        for(int col = 0; col < r; ++col) (*M)(r, col) = (*M)(col, r);
  }
  b.line("detail::opaque(pair_j);");
  return out;
}

void derivativePairs(PassContext & ctx, const std::vector<WorldBody> & w, const std::vector<SubtreeSums> & c,
                     const Eigen::Vector3d & gravity, const std::vector<Force> & fextSums, const std::function<void(int, int, const Scalar &, const Scalar &)> & onEntry)
{
  Block & b = ctx.block();
  const RobotModel & rm = ctx.model();
  const std::size_t n = rm.joints.size();
  // u_k = Ic_i s_k, b_k = dIc_i s_k - s_k x* Hc_i for every dof k (of joint i), kept with s_k in
  // arrays (detail::opaque): they live through all the pairs below
  std::vector<std::vector<Force>> u(n), bk(n);
  std::vector<std::vector<Motion>> s(n);
  const bool stashOn = rm.nv >= kStashDofs;
  if(stashOn) b.line(fmt::format("S pair_u[{0}][6], pair_b[{0}][6], pair_s[{0}][6];", rm.nv));
  auto stash = [&](const std::string & array, int k, const Vec3 & x, const Vec3 & y) {
    std::array<Vec3, 2> out{x, y};
    if(!stashOn) return out;
    std::vector<Scalar *> e;
    for(int i = 0; i < 6; ++i) e.push_back(&out[static_cast<std::size_t>(i / 3)][i % 3]);
    stashScalars(b, array, k, e);
    return out;
  };
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t d = 0; d < w[i].s.size(); ++d)
    {
      const std::string h = fmt::format("{}_{}", rm.joints[i].tag, d);
      const int k = rm.joints[i].vIndex + static_cast<int>(d);
      const Force uk = cg::apply(b, c[i].Ic, w[i].s[d], h + "u");
      const Force bkk = sub(b, apply(b, c[i].Idc, w[i].s[d], h + "Ids"), crossDual(b, w[i].s[d], c[i].Hc, h + "sxH"), h + "b");
      const auto us = stash("pair_u", k, uk.n, uk.f), bs = stash("pair_b", k, bkk.n, bkk.f),
                 ss = stash("pair_s", k, w[i].s[d].w, w[i].s[d].v);
      u[i].push_back(Force{us[0], us[1]});
      bk[i].push_back(Force{bs[0], bs[1]});
      s[i].push_back(Motion{ss[0], ss[1]});
    }
  if(stashOn)
  {
    b.line("detail::opaque(pair_u);");
    b.line("detail::opaque(pair_b);");
    b.line("detail::opaque(pair_s);");
  }
  const std::vector<PairJoint> pj = stashJoints(b, w, c, stashOn);
  // a_0 = [0; -g] as the forward pass uses it (the root's inherited acceleration)
  Motion a0 = Motion::zero();
  for(int i = 0; i < 3; ++i) a0.v[i] = Scalar::constant(-gravity[i]);
  for(std::size_t j = 0; j < n; ++j)
  {
    const MovingJoint & mj = rm.joints[j];
    const bool forward = mj.joint.forward();
    const int p = mj.parent;
    const Motion v_p = p < 0 ? zeroMotion() : pj[static_cast<std::size_t>(p)].v;
    const Motion a_p = p < 0 ? a0 : pj[static_cast<std::size_t>(p)].a;
    // inherited by the subtree of j: of λ(j), or of j when S is carried by the predecessor
    const Motion & wv = forward ? v_p : pj[j].v;
    const Motion & aw = forward ? a_p : pj[j].a;
    const Motion & vCarrier = forward ? pj[j].v : v_p;
    b.comment(fmt::format("{}: d tau / d q and d tau / d alpha, columns of {}", mj.tag, mj.name));
    for(std::size_t d = 0; d < w[j].s.size(); ++d)
    {
      const Motion & sm = s[j][d];
      const int col = mj.vIndex + static_cast<int>(d);
      const std::string h = fmt::format("{}_{}", mj.tag, d);
      // with the inputs in arrays, each column is a function of its own (a lambda the compiler does
      // not inline): register allocation per column rather than over the whole body (compile time)
      if(stashOn) b.line("[&]() RBDGEN_NOINLINE {");
      const Motion yvQ = cross(b, wv, sm, h + "yv");
      const Motion yaQ = add(b, cross(b, aw, sm, h + "axs"), cross(b, cross(b, sm, wv, h + "sxw"), wv, h + "sxwxw"), h + "ya");
      const Motion yaA = add(b, cross(b, vCarrier, sm, h + "sd"), yvQ, h + "yaA");
      // dF of the subtree of j (for the ancestors and for j's own dofs when not carried):
      // dFq = s x* Gc + Ic yaQ + Bc yvQ, dFa = Ic yaA + Bc s, with Bc y = dIc y + y x* Hc
      const bool needDF = p >= 0 || !forward;
      Force dFq, dFa;
      if(needDF)
      {
        const SubtreeSums & cj = pj[j].c;
        dFq = cg::add(b, cg::add(b, crossDual(b, sm, cj.Gc, h + "sxG"), cg::apply(b, cj.Ic, yaQ, h + "Iya"), h + "dFq1"),
                      cg::add(b, apply(b, cj.Idc, yvQ, h + "Idyv"), crossDual(b, yvQ, cj.Hc, h + "yvxH"), h + "dFq2"), h + "dFq");
        dFa = cg::add(b, cg::apply(b, cj.Ic, yaA, h + "IyaA"),
                      cg::add(b, apply(b, cj.Idc, sm, h + "Ids"), crossDual(b, sm, cj.Hc, h + "sxH"), h + "dFa2"), h + "dFa");
      }
      // the subtree of j: joints i >= j whose support path contains j
      for(std::size_t i = j; i < n; ++i)
      {
        bool inSub = false;
        for(int a = static_cast<int>(i); a >= 0 && !inSub; a = rm.joints[static_cast<std::size_t>(a)].parent)
          inSub = a == static_cast<int>(j);
        if(!inSub) continue;
        const bool carried = i != j || forward;
        for(std::size_t e = 0; e < w[i].s.size(); ++e)
        {
          const int row = rm.joints[i].vIndex + static_cast<int>(e);
          const std::string hk = fmt::format("d{}_{}", row, col);
          Scalar dq;
          if(!carried) dq = dot(b, s[i][e], dFq, hk + "q");
          else
          {
            std::vector<Term> t{Term{1.0, {dot(b, yaQ, u[i][e], hk + "qa")}}, Term{1.0, {dot(b, yvQ, bk[i][e], hk + "qv")}}};
            if(!fextSums.empty()) // s_k . (s_m x* Fext_i)
              t.push_back(Term{1.0, {dot(b, s[i][e], crossDual(b, sm, fextSums[i], hk + "sxF"), hk + "qf")}});
            dq = b.sum(t, hk + "q");
          }
          const Scalar da = b.sum({Term{1.0, {dot(b, yaA, u[i][e], hk + "aa")}}, Term{1.0, {dot(b, sm, bk[i][e], hk + "av")}}},
                                  hk + "a");
          onEntry(row, col, dq, da);
        }
      }
      for(int a = p; a >= 0; a = rm.joints[static_cast<std::size_t>(a)].parent)
      {
        const auto ak = static_cast<std::size_t>(a);
        for(std::size_t e = 0; e < w[ak].s.size(); ++e)
        {
          const int row = rm.joints[ak].vIndex + static_cast<int>(e);
          const std::string hk = fmt::format("d{}_{}", row, col);
          onEntry(row, col, dot(b, s[ak][e], dFq, hk + "q"), dot(b, s[ak][e], dFa, hk + "a"));
        }
      }
      if(stashOn) b.line("}();");
    }
  }
}

} // namespace rbdgen::passes
