#include "DynamicsDerivatives.h"

#include <algorithm>
#include <array>
#include <tuple>

#include <fmt/format.h>

#include "BackwardForce.h"

namespace rbdgen::passes
{

namespace
{

/// dI/dt x = [J w + hd x v; -hd x w]: the rigid-body layout without mass
Force apply(Block & b, const InertiaRate & R, const Motion & x, const std::string & hint)
{
  return applyRigidLayout(b, R.J, R.hd, nullptr, x,
                          [&](const char * part, int i) { return fmt::format("{}{}{}", hint, part, i); });
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
      // on the diagonal A + A^T and h u^T + u h^T are twice one product
      const double twice = r == c ? 2.0 : 1.0;
      std::vector<Term> t = A(r, c, twice);
      if(r != c)
        for(Term & x : A(c, r, 1.0)) t.push_back(x);
      t.push_back(Term{-twice, {I.h[r], v.v[c]}});
      if(r != c) t.push_back(Term{-1.0, {v.v[r], I.h[c]}});
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

/// From this many moving joints on, subtreeSums computes the per-body terms across bodies (SIMD
/// lanes, detail::world_body_terms) rather than as straight-line code per body, and DerivativePairs
/// the rows and column terms of the one-dof joints across joints (detail::column_terms): the
/// inverse_dynamics_derivatives of talos_reduced + free base (33 joints) 5.70 -> 4.96 us (bodies)
/// -> 3.74-4.08 us (joints) with g++ 12, 6.31 -> 4.81 -> 3.84 us with clang++ 14; solo12 + free base
/// (13 joints) 1.90 -> 1.96 -> 1.33 us (g++), 1.89 -> 1.58 -> 1.56 us (clang++) (AVX-512, own
/// program, medians of 7 alternating runs; bench/results/2026-11-29-AMD-EPYC-pinocchio-lanes.md).
/// From 4 rather than 8 since the code's size counts as much as its operations: ur5 (6 joints) in
/// lanes has an inverse_dynamics_derivatives of 19 KB instead of 29-32 KB, and its
/// forward_dynamics_derivatives (with nonlinear_effects, the factors and the products, ~38 KB in all
/// instead of ~50, against a 32 KB instruction cache) 808 -> 700 ns with g++ 12, 775 -> 583 ns with
/// clang++ 14, though the ID derivatives alone go 342 -> 381-390 ns (medians of 11 and 7 alternating runs).
constexpr std::size_t kBodiesAcross = 4;
/// The bodies' arrays have a multiple of this many lanes (8 doubles: AVX-512's packet).
constexpr std::size_t kBodyPad = 8;

/// count rounded up to whole lanes of kBodyPad
std::size_t padToLanes(std::size_t count)
{
  return (count + kBodyPad - 1) / kBodyPad * kBodyPad;
}

/// lanes [count, lanes) of every row of the lane array `name` set to zero (nothing when none)
void zeroPaddingLanes(Block & b, const std::string & name, std::size_t count, std::size_t lanes)
{
  if(lanes > count) b.line(fmt::format("for(auto & row : {}) for(int k = {}; k < {}; ++k) row[k] = S(0);", name, count, lanes));
}

/// x m
Motion scale(Block & b, const Scalar & x, const Motion & m, const std::string & hint)
{
  return {cg::scale(b, x, m.w, hint + "_w"), cg::scale(b, x, m.v, hint + "_v")};
}

} // namespace

/// Blocks of rows are computed over a multiple of this many rows (AVX-512's 8 doubles; Eigen
/// vectorises a fixed size with the widest packet that divides it), the matrices of the blocks
/// having as many zero rows past nv.
constexpr int kBlockPad = 8;

std::string BlockEntries::into(const std::string & column) const
{
  std::string cs, ys;
  for(std::size_t k = 0; k < cols.size(); ++k)
  {
    cs += fmt::format(", {}", cols[k]);
    ys += (k ? ", " : "") + y[k];
  }
  const int padded = (rows + kBlockPad - 1) / kBlockPad * kBlockPad;
  return fmt::format("{}.template segment<{}>({}) = detail::rows_times<{}{}>({}, {}, {{{}}}){};", column, rows, first, padded, cs,
                     M, first, ys, padded == rows ? "" : fmt::format(".template head<{}>()", rows));
}

std::vector<WorldBody> worldBodies(PassContext & ctx, const std::vector<Xform> & X0, bool velocity, const Motion & a0, bool acceleration)
{
  Block & b = ctx.block();
  std::vector<WorldBody> out(ctx.model().joints.size());
  for(int k : ctx.allJoints())
  {
    const auto kk = static_cast<std::size_t>(k);
    const MovingJoint & mj = ctx.joint(k);
    const JointKernel & K = ctx.kernel(k);
    WorldBody & w = out[kk];
    const WorldBody * parent = mj.parent < 0 ? nullptr : &out[static_cast<std::size_t>(mj.parent)];
    b.comment(fmt::format("{}: world s, v, a", mj.tag));
    for(std::size_t d = 0; d < K.S.size(); ++d) w.s.push_back(invApply(b, X0[kk], K.S[d], fmt::format("{}_s{}", mj.tag, d)));
    // vJ = s alpha, aJ = s alphaD (world)
    Motion vJ = Motion::zero(), aJ = Motion::zero();
    for(std::size_t d = 0; d < w.s.size(); ++d)
    {
      const int i = mj.vIndex + static_cast<int>(d);
      const std::string h = fmt::format("{}_{}", mj.tag, d);
      if(velocity) vJ = add(b, vJ, scale(b, Scalar::var(fmt::format("alpha[{}]", i)), w.s[d], h + "_vJ"), mj.tag + "_vJw");
      if(acceleration) aJ = add(b, aJ, scale(b, Scalar::var(fmt::format("alphaD[{}]", i)), w.s[d], h + "_aJ"), mj.tag + "_aJw");
    }
    // v = v_p + vJ, a = a_p + aJ + v_p x vJ
    w.v = parent ? add(b, parent->v, vJ, mj.tag + "_vw") : vJ;
    w.a = add(b, parent ? parent->a : a0, aJ, mj.tag + "_aw0");
    if(parent && velocity) w.a = add(b, w.a, cross(b, parent->v, vJ, mj.tag + "_vxvJ"), mj.tag + "_aw");
  }
  return out;
}

namespace
{

/// The per-body terms of subtreeSums as the rows of arrays, computed across bodies by
/// detail::world_body_terms (SIMD lanes over bodies): per body k, its world I, h = I v, g and dI/dt
/// read back from `wb_out[row][k]`.
struct BodyTerms
{
  Inertia I;
  Force h, g;
  InertiaRate Id;
};

std::vector<BodyTerms> bodyTermsAcrossBodies(Block & b, const RobotModel & rm, const std::vector<Xform> & X0, const std::vector<WorldBody> & w)
{
  const std::size_t n = rm.joints.size();
  const std::size_t lanes = padToLanes(n);
  b.comment(fmt::format("world I, I v, I a + v x* I v and dI/dt of every body, across bodies (detail::world_body_terms; "
                        "lanes {} to {}: zero)", n, lanes - 1));
  b.line(fmt::format("S wb_in[24][{}];", lanes));
  b.homeCopiesIn("wb_in");
  b.line(fmt::format("S wb_out[30][{}];", lanes));
  auto constant = [](const Scalar & x) { return x.label().empty() ? fmt::format("{}", x.value()) : x.label(); };
  std::vector<std::string> rows(10);
  for(std::size_t k = 0; k < lanes; ++k)
  {
    if(k >= n)
    {
      for(std::string & row : rows) row += ", 0.0";
      continue;
    }
    const Inertia Ib = bodyInertia(rm.joints[k]);
    const Scalar * c[10] = {&Ib.m, &Ib.h[0], &Ib.h[1], &Ib.h[2], &Ib.I(0, 0), &Ib.I(0, 1), &Ib.I(0, 2), &Ib.I(1, 1), &Ib.I(1, 2), &Ib.I(2, 2)};
    for(int i = 0; i < 10; ++i) rows[static_cast<std::size_t>(i)] += (k ? ", " : "") + constant(*c[i]);
    std::vector<const Scalar *> in;
    for(int i = 0; i < 9; ++i) in.push_back(&X0[k].E(i / 3, i % 3));
    for(int i = 0; i < 3; ++i) in.push_back(&X0[k].r[i]);
    for(const Motion * m : {&w[k].v, &w[k].a})
      for(const Vec3 * x : {&m->w, &m->v})
        for(int i = 0; i < 3; ++i) in.push_back(&(*x)[i]);
    for(std::size_t i = 0; i < in.size(); ++i) b.line(fmt::format("wb_in[{}][{}] = {};", i, k, Block::text(*in[i])));
  }
  zeroPaddingLanes(b, "wb_in", n, lanes);
  std::string table;
  for(const std::string & row : rows) table += (table.empty() ? "{" : ", {") + row + "}";
  b.line(fmt::format("static constexpr double wb_inertia[10][{}] = {{{}}};", lanes, table));
  b.line("detail::world_body_terms<S>(wb_in, wb_inertia, wb_out);");
  std::vector<BodyTerms> out(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    const auto v = [&](int row) { return Scalar::var(fmt::format("wb_out[{}][{}]", row, k)); };
    BodyTerms & t = out[k];
    t.I.m = bodyInertia(rm.joints[k]).m;
    const int sym[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
    for(int i = 0; i < 3; ++i)
    {
      t.I.h[i] = v(i);
      t.h.n[i] = v(9 + i);
      t.h.f[i] = v(12 + i);
      t.g.n[i] = v(15 + i);
      t.g.f[i] = v(18 + i);
      t.Id.hd[i] = v(27 + i);
      for(int j = 0; j < 3; ++j)
      {
        t.I.I(i, j) = v(3 + sym[i][j]);
        t.Id.J(i, j) = v(21 + sym[i][j]);
      }
    }
  }
  return out;
}

} // namespace

std::vector<SubtreeSums> subtreeSums(PassContext & ctx, const std::vector<Xform> & X0, const std::vector<WorldBody> & w)
{
  Block & b = ctx.block();
  const RobotModel & rm = ctx.model();
  const std::size_t n = rm.joints.size();
  std::vector<SubtreeSums> c(n);
  std::vector<bool> started(n, false); // c[k] holds the sums of some of k's children
  const std::vector<BodyTerms> across = n >= kBodiesAcross ? bodyTermsAcrossBodies(b, rm, X0, w) : std::vector<BodyTerms>{};
  for(std::size_t k = n; k-- > 0;)
  {
    const MovingJoint & mj = rm.joints[k];
    const std::string & t = mj.tag;
    b.comment(fmt::format("{}: world I, I v, I a + v x* I v, dI/dt, then the sums over its subtree", t));
    Inertia I;
    Force h, g;
    InertiaRate Id;
    if(!across.empty()) std::tie(I, h, g, Id) = std::tie(across[k].I, across[k].h, across[k].g, across[k].Id);
    else
    {
      I = transApply(b, X0[k], bodyInertia(mj), t + "_Iw");
      h = cg::apply(b, I, w[k].v, t + "_hw");
      g = cg::add(b, cg::apply(b, I, w[k].a, t + "_Ia"), crossDual(b, w[k].v, h, t + "_vxh"), t + "_gw");
      Id = inertiaRate(b, I, w[k].v, t + "_Id");
    }
    if(started[k])
    {
      const std::string hc = t + "c";
      c[k] = {cg::add(b, c[k].Ic, I, hc + "_I"), add(b, c[k].Idc, Id, hc + "_Id"), cg::add(b, c[k].Hc, h, hc + "_H"),
              cg::add(b, c[k].Gc, g, hc + "_G")};
    }
    else c[k] = {I, Id, h, g};
    if(mj.parent < 0) continue;
    // into the parent's sums (children come after their parent: the parent is still ahead)
    const auto pk = static_cast<std::size_t>(mj.parent);
    if(!started[pk]) c[pk] = c[k];
    else
    {
      const std::string hp = rm.joints[pk].tag + "s";
      c[pk] = {cg::add(b, c[pk].Ic, c[k].Ic, hp + "_I"), add(b, c[pk].Idc, c[k].Idc, hp + "_Id"), cg::add(b, c[pk].Hc, c[k].Hc, hp + "_H"),
               cg::add(b, c[pk].Gc, c[k].Gc, hp + "_G")};
    }
    started[pk] = true;
  }
  return c;
}

/// From this many dofs on, the pairs' long-lived inputs go through arrays (detail::opaque) and each
/// column is an out-of-line lambda: g++ -O2 on talos_reduced (38 dofs): 85 s -> 44 s (arrays) -> 26 s
/// (columns; 66 s on the same day without them) for inverse_dynamics_derivatives, as fast at run time
/// (8.3-9.0 us vs 9.6-9.9 us); below it the registers win (ur5e: 650 ns in registers, 1,350 ns
/// through the arrays).
constexpr int kStashDofs = 24;

bool derivativesInArrays(const RobotModel & rm)
{
  return rm.nv >= kStashDofs;
}

/// From this many rows on, a column's entries in the subtree of its joint, or in a run of consecutive
/// ancestor dofs, are one vector expression (onBlock).
constexpr int kBlockRows = 2;
/// Blocks only for a tree with a subtree of at least this many dofs: on the 6- and 7-dof arms
/// (subtrees of 1 to 7 rows) the ID derivatives ran as fast with blocks as without, and g++'s
/// forward_dynamics_derivatives of ur5 (which calls them) 18 % slower (910 -> 1,100 ns).
constexpr int kBlockRobotRows = 8;

namespace
{

/// true when joint j is on joint i's support path (i in the subtree of j, i = j included).
bool inSubtree(const RobotModel & rm, std::size_t i, std::size_t j)
{
  for(int a = static_cast<int>(i); a >= 0; a = rm.joints[static_cast<std::size_t>(a)].parent)
    if(a == static_cast<int>(j)) return true;
  return false;
}

/// The dofs of joint j's subtree as one index range [first, first + count) (RBDyn numbers dofs
/// depth first, so a subtree's are contiguous); count = 0 when they are not.
std::pair<int, int> subtreeDofs(const RobotModel & rm, std::size_t j)
{
  int lo = rm.nv, hi = -1, count = 0;
  for(std::size_t i = j; i < rm.joints.size(); ++i)
  {
    if(!inSubtree(rm, i, j) || rm.joints[i].nv == 0) continue;
    lo = std::min(lo, rm.joints[i].vIndex);
    hi = std::max(hi, rm.joints[i].vIndex + rm.joints[i].nv);
    count += rm.joints[i].nv;
  }
  if(count == 0 || hi - lo != count) return {0, 0};
  return {lo, count};
}

/// [w; v] or [n; f] of each vector, in order, as one list of scalars.
std::vector<Scalar> components(const std::vector<std::array<const Vec3 *, 2>> & vectors)
{
  std::vector<Scalar> out;
  for(const auto & [x, y] : vectors)
    for(const Vec3 * p : {x, y})
      for(int i = 0; i < 3; ++i) out.push_back((*p)[i]);
  return out;
}

/// rows [first, first + rows) of M y, y's zero components left out
BlockEntries blockColumn(const std::string & M, const std::vector<Scalar> & y, int first, int rows)
{
  BlockEntries e{M, first, rows, {}, {}};
  for(std::size_t c = 0; c < y.size(); ++c)
    if(!y[c].isZero())
    {
      e.cols.push_back(static_cast<int>(c));
      e.y.push_back(Block::text(y[c]));
    }
  return e;
}

/// The world quantities of a joint the columns read (v, a, composite sums).
struct PairJoint
{
  Motion v, a;
  SubtreeSums c;
};

/// derivativePairs in two steps: joint(k, c_k) emits the rows u_k, b_k of joint k's dofs (and
/// stashes what the columns read), columns() every column. (Emitting each joint's rows as soon as its
/// sums were complete, leaves first, ran slower: 6 code layouts, g++, medians ur5 346 -> 456 ns,
/// talos_reduced 5.75 -> 5.87 us.)
class DerivativePairs
{
public:
  using EntryFn = std::function<void(int row, int col, const Scalar & dq, const Scalar & da)>;
  using BlockFn = std::function<void(int col, const BlockEntries & dq, const BlockEntries & da)>;
  DerivativePairs(PassContext & ctx, const std::vector<WorldBody> & w, const Eigen::Vector3d & gravity,
                  const std::vector<Force> & fextSums, EntryFn onEntry, BlockFn onBlock = {});
  void joint(int k, const SubtreeSums & c);
  void columns();

private:
  PassContext & ctx_;
  const std::vector<WorldBody> & w_;
  Eigen::Vector3d gravity_;
  std::vector<Force> fextSums_;
  EntryFn onEntry_;
  BlockFn onBlock_;
  bool stashOn_ = false, blocks_ = false;
  std::vector<int> lane_;                 ///< per joint: its lane of detail::column_terms, or -1
  std::vector<std::size_t> laneJoint_;    ///< per lane: its joint
  std::vector<std::vector<Force>> u_, b_; ///< per joint, per dof: u_k, b_k (or their slots)
  std::vector<std::vector<Motion>> s_;    ///< per joint, per dof: s_k (or its slots)
  std::vector<PairJoint> pj_;
};

DerivativePairs::DerivativePairs(PassContext & ctx, const std::vector<WorldBody> & w, const Eigen::Vector3d & gravity,
                                 const std::vector<Force> & fextSums, EntryFn onEntry, BlockFn onBlock)
    : ctx_(ctx), w_(w), gravity_(gravity), fextSums_(fextSums), onEntry_(std::move(onEntry)), onBlock_(std::move(onBlock))
{
  Block & b = ctx.block();
  const RobotModel & rm = ctx.model();
  const std::size_t n = rm.joints.size();
  u_.resize(n);
  b_.resize(n);
  s_.resize(n);
  pj_.resize(n);
  stashOn_ = derivativesInArrays(rm);
  // blocks: a column's entries over contiguous rows as one product of rows of UB = [u_k^T b_k^T]
  // (nv x 12, row k per dof) or of SM = [s_k^T] (nv x 6); on trees with a subtree of kBlockRobotRows
  // dofs or more, without external wrenches (they add a term per row)
  for(std::size_t j = 0; j < n && onBlock_ && fextSums.empty(); ++j)
    blocks_ = blocks_ || (rm.joints[j].joint.forward() && subtreeDofs(rm, j).second >= kBlockRobotRows);
  // (kBlockPad more rows, zero: blocks are computed over a multiple of kBlockPad rows)
  if(blocks_)
  {
    b.line(fmt::format("Eigen::Matrix<S, {}, 12> pair_ub;", rm.nv + kBlockPad));
    b.line(fmt::format("Eigen::Matrix<S, {}, 6> pair_sm;", rm.nv + kBlockPad));
    b.line(fmt::format("pair_ub.template bottomRows<{}>().setZero();", kBlockPad));
    b.line(fmt::format("pair_sm.template bottomRows<{}>().setZero();", kBlockPad));
  }
  if(stashOn_ && !blocks_) b.line(fmt::format("S pair_u[{0}][6], pair_b[{0}][6], pair_s[{0}][6];", rm.nv));
  if(stashOn_) b.line(fmt::format("S pair_j[{}][43];", std::max<std::size_t>(n, 1)));
  // (the values these arrays copy are computed into them: HomeInSlots.h; the columns read pair_j
  // slot by slot, so what it copies from another array is read there)
  for(const char * a : {"pair_ub", "pair_sm", "pair_u", "pair_b", "pair_s"}) b.homeCopiesIn(a);
  b.homeCopiesIn("pair_j", true);
  // the one-dof forward joints with a parent: their rows u, b and their columns' yaQ, yvQ, yaA, dFq,
  // dFa across joints in SIMD lanes (detail::column_terms), inputs written by joint()
  lane_.assign(n, -1);
  for(std::size_t j = 0; j < n && n >= kBodiesAcross; ++j)
    if(rm.joints[j].nv == 1 && rm.joints[j].joint.forward() && rm.joints[j].parent >= 0)
    {
      lane_[j] = static_cast<int>(laneJoint_.size());
      laneJoint_.push_back(j);
    }
  if(!laneJoint_.empty())
  {
    const std::size_t lanes = padToLanes(laneJoint_.size());
    b.line(fmt::format("S ct_in[49][{}];", lanes));
    b.homeCopiesIn("ct_in");
    b.line(fmt::format("S ct_out[42][{}];", lanes));
  }
}

void DerivativePairs::joint(int k, const SubtreeSums & c)
{
  Block & b = ctx_.block();
  const RobotModel & rm = ctx_.model();
  const auto i = static_cast<std::size_t>(k);
  // row k of matrix M (pair_ub, pair_sm): every entry written, its variables then read from M
  auto intoMatrix = [&](const std::string & M, int row, std::vector<Scalar *> e) {
    for(std::size_t x = 0; x < e.size(); ++x)
    {
      const std::string slot = fmt::format("{}({}, {})", M, row, x);
      b.line(fmt::format("{} = {};", slot, Block::text(*e[x])));
      if(!e[x]->isConst()) *e[x] = Scalar::var(slot);
    }
  };
  auto stash = [&](const std::string & array, int row, const Vec3 & x, const Vec3 & y) {
    std::array<Vec3, 2> out{x, y};
    if(!stashOn_) return out;
    std::vector<Scalar *> e;
    for(int z = 0; z < 6; ++z) e.push_back(&out[static_cast<std::size_t>(z / 3)][z % 3]);
    stashScalars(b, array, row, e);
    return out;
  };
  // a lane's inputs of detail::column_terms: its parent's world v and a, s, Gc, Hc, Ic, dIc/dt
  // (its row u, b comes from column_terms, in columns())
  const int lane = lane_[i];
  if(lane >= 0)
  {
    const WorldBody & wp = w_[static_cast<std::size_t>(rm.joints[i].parent)];
    std::vector<const Scalar *> in;
    const auto vec = [&](const Vec3 & x) {
      for(int z = 0; z < 3; ++z) in.push_back(&x[z]);
    };
    for(const Vec3 * x : {&wp.v.w, &wp.v.v, &wp.a.w, &wp.a.v, &w_[i].s[0].w, &w_[i].s[0].v, &c.Gc.n, &c.Gc.f, &c.Hc.n, &c.Hc.f})
      vec(*x);
    in.push_back(&c.Ic.m);
    vec(c.Ic.h);
    for(const Mat3 * M : {&c.Ic.I, &c.Idc.J})
      for(int r = 0; r < 3; ++r)
        for(int col = r; col < 3; ++col) in.push_back(&(*M)(r, col));
    vec(c.Idc.hd);
    for(std::size_t x = 0; x < in.size(); ++x) b.line(fmt::format("ct_in[{}][{}] = {};", x, lane, Block::text(*in[x])));
  }
  // u_k = Ic_i s_k, b_k = dIc_i s_k - s_k x* Hc_i for every dof of joint i (with s_k in arrays when
  // stashed: they live through all the columns)
  for(std::size_t d = 0; d < w_[i].s.size(); ++d)
  {
    const std::string h = fmt::format("{}_{}", rm.joints[i].tag, d);
    const int row = rm.joints[i].vIndex + static_cast<int>(d);
    Force uk, bkk;
    if(lane < 0)
    {
      uk = cg::apply(b, c.Ic, w_[i].s[d], h + "u");
      bkk = sub(b, apply(b, c.Idc, w_[i].s[d], h + "Ids"), crossDual(b, w_[i].s[d], c.Hc, h + "sxH"), h + "b");
    }
    Motion sk = w_[i].s[d];
    if(blocks_)
    {
      if(lane < 0)
        intoMatrix("pair_ub", row, {&uk.n[0], &uk.n[1], &uk.n[2], &uk.f[0], &uk.f[1], &uk.f[2], &bkk.n[0], &bkk.n[1], &bkk.n[2],
                                    &bkk.f[0], &bkk.f[1], &bkk.f[2]});
      intoMatrix("pair_sm", row, {&sk.w[0], &sk.w[1], &sk.w[2], &sk.v[0], &sk.v[1], &sk.v[2]});
    }
    else
    {
      if(lane < 0)
      {
        const auto us = stash("pair_u", row, uk.n, uk.f), bs = stash("pair_b", row, bkk.n, bkk.f);
        uk = Force{us[0], us[1]};
        bkk = Force{bs[0], bs[1]};
      }
      const auto ss = stash("pair_s", row, sk.w, sk.v);
      sk = Motion{ss[0], ss[1]};
    }
    u_[i].push_back(uk);
    b_[i].push_back(bkk);
    s_[i].push_back(sk);
  }
  // the world quantities the columns read (v, a, composite sums), kept in pair_j[k] when stashed
  PairJoint & p = pj_[i];
  p = PairJoint{w_[i].v, w_[i].a, c};
  if(!stashOn_) return;
  std::vector<Scalar *> e;
  for(Vec3 * x : {&p.v.w, &p.v.v, &p.a.w, &p.a.v})
    for(int z = 0; z < 3; ++z) e.push_back(&(*x)[z]);
  // (a lane's sums: read by column_terms only, from ct_in)
  if(lane >= 0)
  {
    stashScalars(b, "pair_j", k, e);
    return;
  }
  for(Vec3 * x : {&p.c.Ic.h, &p.c.Idc.hd, &p.c.Hc.n, &p.c.Hc.f, &p.c.Gc.n, &p.c.Gc.f})
    for(int z = 0; z < 3; ++z) e.push_back(&(*x)[z]);
  e.push_back(&p.c.Ic.m);
  // symmetric 3x3: the upper triangle, the lower one mirrors it
  for(Mat3 * M : {&p.c.Ic.I, &p.c.Idc.J})
    for(int r = 0; r < 3; ++r)
      for(int col = r; col < 3; ++col) e.push_back(&(*M)(r, col));
  stashScalars(b, "pair_j", k, e);
  for(Mat3 * M : {&p.c.Ic.I, &p.c.Idc.J})
    for(int r = 0; r < 3; ++r)
      for(int col = 0; col < r; ++col) (*M)(r, col) = (*M)(col, r);
}

void DerivativePairs::columns()
{
  Block & b = ctx_.block();
  const RobotModel & rm = ctx_.model();
  const std::size_t n = rm.joints.size();
  const std::vector<WorldBody> & w = w_;
  const std::vector<std::vector<Force>> & u = u_;
  const std::vector<std::vector<Force>> & bk = b_;
  const std::vector<std::vector<Motion>> & s = s_;
  const std::vector<PairJoint> & pj = pj_;
  const std::vector<Force> & fextSums = fextSums_;
  const bool stashOn = stashOn_, blocks = blocks_;
  // rows [first, first + rows) of column col: M (pair_ub or pair_sm) times yq and ya
  auto emitBlock = [&](const std::string & M, const std::vector<Scalar> & yq, const std::vector<Scalar> & ya, int first,
                       int rows, int col) { onBlock_(col, blockColumn(M, yq, first, rows), blockColumn(M, ya, first, rows)); };
  const Eigen::Vector3d & gravity = gravity_;
  // a_0 = [0; -g] as the forward pass uses it (the root's inherited acceleration)
  Motion a0 = Motion::zero();
  for(int i = 0; i < 3; ++i) a0.v[i] = Scalar::constant(-gravity[i]);
  // the lanes' rows u, b and columns' terms (detail::column_terms), then their rows into pair_ub
  // (blocks) or read from ct_out
  if(!laneJoint_.empty())
  {
    const std::size_t lanes = padToLanes(laneJoint_.size());
    b.comment(fmt::format("rows u, b and yaQ, yvQ, yaA, dFq, dFa of the one-dof joints, across joints (detail::column_terms; "
                          "lanes {} to {}: zero)", laneJoint_.size(), lanes - 1));
    zeroPaddingLanes(b, "ct_in", laneJoint_.size(), lanes);
    // the rows u, b straight into pair_ub when the lanes' dofs are its last rows, in order (the
    // padding lanes then write zeros into its zero rows past nv)
    const int r0 = rm.joints[laneJoint_.front()].vIndex;
    bool direct = blocks && r0 + static_cast<int>(laneJoint_.size()) == rm.nv && static_cast<int>(lanes - laneJoint_.size()) <= kBlockPad;
    for(std::size_t l = 0; l < laneJoint_.size() && direct; ++l) direct = rm.joints[laneJoint_[l]].vIndex == r0 + static_cast<int>(l);
    b.line(direct ? fmt::format("detail::column_terms<S>(ct_in, ct_out, pair_ub.data() + {}, {});", r0, rm.nv + kBlockPad)
                  : "detail::column_terms<S>(ct_in, ct_out);");
    for(std::size_t l = 0; l < laneJoint_.size(); ++l)
    {
      const std::size_t j = laneJoint_[l];
      const int row = rm.joints[j].vIndex;
      Force uk, bkk;
      const auto out = [&](int x) {
        return Scalar::var(direct ? fmt::format("pair_ub({}, {})", row, x) : fmt::format("ct_out[{}][{}]", 30 + x, l));
      };
      for(int z = 0; z < 3; ++z)
      {
        uk.n[z] = out(z);
        uk.f[z] = out(3 + z);
        bkk.n[z] = out(6 + z);
        bkk.f[z] = out(9 + z);
      }
      if(blocks && !direct)
      {
        const std::vector<Scalar *> e{&uk.n[0],  &uk.n[1],  &uk.n[2],  &uk.f[0],  &uk.f[1],  &uk.f[2],
                                      &bkk.n[0], &bkk.n[1], &bkk.n[2], &bkk.f[0], &bkk.f[1], &bkk.f[2]};
        for(std::size_t x = 0; x < e.size(); ++x)
        {
          const std::string slot = fmt::format("pair_ub({}, {})", row, x);
          b.line(fmt::format("{} = {};", slot, Block::text(*e[x])));
          *e[x] = Scalar::var(slot);
        }
      }
      u_[j][0] = uk;
      b_[j][0] = bkk;
    }
  }
  if(stashOn)
  {
    std::vector<std::string> arrays =
        blocks ? std::vector<std::string>{"pair_ub.data()", "pair_sm.data()"} : std::vector<std::string>{"pair_u", "pair_b", "pair_s"};
    arrays.push_back("pair_j");
    if(!laneJoint_.empty()) arrays.push_back("ct_out");
    for(const std::string & a : arrays) b.line(fmt::format("detail::opaque({});", a));
  }
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
      const bool needDF = p >= 0 || !forward;
      Motion yvQ, yaQ, yaA;
      Force dFq, dFa;
      if(lane_[j] >= 0)
      {
        const auto v = [&](int row) { return Scalar::var(fmt::format("ct_out[{}][{}]", row, lane_[j])); };
        for(int i = 0; i < 3; ++i)
        {
          yaQ.w[i] = v(i);
          yaQ.v[i] = v(3 + i);
          yvQ.w[i] = v(6 + i);
          yvQ.v[i] = v(9 + i);
          yaA.w[i] = v(12 + i);
          yaA.v[i] = v(15 + i);
          dFq.n[i] = v(18 + i);
          dFq.f[i] = v(21 + i);
          dFa.n[i] = v(24 + i);
          dFa.f[i] = v(27 + i);
        }
      }
      else
      {
        yvQ = cross(b, wv, sm, h + "yv");
        yaQ = add(b, cross(b, aw, sm, h + "axs"), cross(b, wv, yvQ, h + "wxyv"), h + "ya");
        // sdot_m = vCarrier x s_m; of a 1-dof joint carried by its body v_j x s_m = (w + s_m alpha_m) x s_m
        // = w x s_m, so yaA = 2 yvQ
        yaA = forward && w[j].s.size() == 1 ? scale(b, Scalar::constant(2.0), yvQ, h + "yaA")
                                            : add(b, cross(b, vCarrier, sm, h + "sd"), yvQ, h + "yaA");
        // dF of the subtree of j (for the ancestors and for j's own dofs when not carried):
        // dFq = s x* Gc + Ic yaQ + Bc yvQ, dFa = Ic yaA + Bc s, with Bc y = dIc y + y x* Hc
        if(needDF)
        {
          const SubtreeSums & cj = pj[j].c;
          dFq = cg::add(b, cg::add(b, crossDual(b, sm, cj.Gc, h + "sxG"), cg::apply(b, cj.Ic, yaQ, h + "Iya"), h + "dFq1"),
                        cg::add(b, apply(b, cj.Idc, yvQ, h + "Idyv"), crossDual(b, yvQ, cj.Hc, h + "yvxH"), h + "dFq2"), h + "dFq");
          // dIc s + s x* Hc = b_m + 2 s x* Hc (b_m: the row of the column's own dof)
          const Force sxH = crossDual(b, sm, cj.Hc, h + "sxH");
          dFa = cg::add(b, cg::apply(b, cj.Ic, yaA, h + "IyaA"),
                        cg::add(b, bk[j][d], cg::add(b, sxH, sxH, h + "2sxH"), h + "dFa2"), h + "dFa");
        }
      }
      // the subtree of j: joints i >= j whose support path contains j; as one block of rows
      // [first, first + rows) of UB times Yq = [yaQ; yvQ] and Ya = [yaA; s] when its dofs are
      // contiguous and each is carried (j forward)
      const auto [first, rows] = blocks && forward ? subtreeDofs(rm, j) : std::pair<int, int>{0, 0};
      if(rows >= kBlockRows)
        emitBlock("pair_ub", components({{&yaQ.w, &yaQ.v}, {&yvQ.w, &yvQ.v}}), components({{&yaA.w, &yaA.v}, {&sm.w, &sm.v}}),
                  first, rows, col);
      else
      {
        for(std::size_t i = j; i < n; ++i)
        {
          if(!inSubtree(rm, i, j)) continue;
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
            onEntry_(row, col, dq, da);
          }
        }
      }
      // the strict ancestors of j: s_k . dF; with blocks, each run of consecutive dofs as one block
      // of rows of the matrix of the s_k (SM, nv x 6) times dFq and dFa
      std::vector<std::pair<int, const Motion *>> ancestors; // (dof, s)
      for(int a = p; a >= 0; a = rm.joints[static_cast<std::size_t>(a)].parent)
      {
        const auto ak = static_cast<std::size_t>(a);
        for(std::size_t e = 0; e < w[ak].s.size(); ++e) ancestors.emplace_back(rm.joints[ak].vIndex + static_cast<int>(e), &s[ak][e]);
      }
      if(blocks) std::sort(ancestors.begin(), ancestors.end(), [](const auto & x, const auto & y) { return x.first < y.first; });
      for(std::size_t r0 = 0, r1 = 0; r0 < ancestors.size(); r0 = r1)
      {
        for(r1 = r0 + 1; r1 < ancestors.size() && ancestors[r1].first == ancestors[r1 - 1].first + 1;) ++r1;
        const int run = static_cast<int>(r1 - r0);
        if(blocks && run >= kBlockRows)
        {
          emitBlock("pair_sm", components({{&dFq.n, &dFq.f}}), components({{&dFa.n, &dFa.f}}), ancestors[r0].first, run, col);
          continue;
        }
        for(std::size_t r = r0; r < r1; ++r)
        {
          const int row = ancestors[r].first;
          const std::string hk = fmt::format("d{}_{}", row, col);
          onEntry_(row, col, dot(b, *ancestors[r].second, dFq, hk + "q"), dot(b, *ancestors[r].second, dFa, hk + "a"));
        }
      }
      if(stashOn) b.line("}();");
    }
  }
}

} // namespace

void derivativePairs(PassContext & ctx, const std::vector<WorldBody> & w, const std::vector<SubtreeSums> & c,
                     const Eigen::Vector3d & gravity, const std::vector<Force> & fextSums,
                     const std::function<void(int, int, const Scalar &, const Scalar &)> & onEntry,
                     const std::function<void(int, const BlockEntries &, const BlockEntries &)> & onBlock)
{
  DerivativePairs pairs(ctx, w, gravity, fextSums, onEntry, onBlock);
  for(std::size_t k = 0; k < c.size(); ++k) pairs.joint(static_cast<int>(k), c[k]);
  pairs.columns();
}

} // namespace rbdgen::passes
