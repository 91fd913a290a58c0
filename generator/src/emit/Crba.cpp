// Mass matrix (composite rigid-body algorithm: the composite-inertia pass, then each column's
// force F = Ic S carried along the support path to the root) and forward dynamics by CRBA + a
// tree-sparse L^T D L factorisation (Featherstone, RBDA 6.5).
#include <algorithm>
#include <fmt/format.h>

#include "../passes/CompositeInertia.h"
#include "../passes/SharedPasses.h"
#include "Functions.h"
#include "Template.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

namespace
{

// Composite rigid-body algorithm on symbols: H (lower triangle, by dof index) from kernels. Joint k's
// columns come right after its composite inertia is complete (leaves first; on a large tree, whose
// body computes the composite inertias in place, next to them); entry(r, c, H_rc) runs as each
// entry of the lower triangle (r >= c) is emitted.
std::vector<std::vector<Scalar>> emitCrba(PassContext & ctx, const std::function<void(int r, int c, Scalar & x)> & entry)
{
  Block & b = ctx.block();
  const RobotModel & rm = ctx.model();
  std::vector<std::vector<Scalar>> H(static_cast<std::size_t>(rm.nv),
                                     std::vector<Scalar>(static_cast<std::size_t>(rm.nv), Scalar::constant(0)));
  const auto put = [&](int r, int c, const Scalar & x) {
    Scalar & h = H[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
    h = x;
    entry(r, c, h);
  };
  compositeInertias(ctx, [&](int k, const Inertia & Ic) {
    const MovingJoint & mj = ctx.joint(k);
    b.comment(fmt::format("{}: mass matrix columns, F = Ic S carried to the root", mj.tag));
    for(int d = 0; d < mj.nv; ++d)
    {
      const std::string h = fmt::format("{}_F{}", mj.tag, d);
      Force F = apply(b, Ic, ctx.kernel(k).S[static_cast<std::size_t>(d)], h);
      const int col = mj.vIndex + d;
      // H_kk block (lower part: rows >= col)
      const auto own = projectForce(b, ctx.kernel(k), F, fmt::format("H_{}", col));
      for(int e = d; e < mj.nv; ++e) put(mj.vIndex + e, col, own[static_cast<std::size_t>(e)]);
      int j = k;
      while(ctx.joint(j).parent >= 0)
      {
        const MovingJoint & mjj = ctx.joint(j);
        F = toParent(b, mjj, ctx.kernel(j), F, fmt::format("{}_{}", h, mjj.tag));
        j = mjj.parent;
        const MovingJoint & mp = ctx.joint(j);
        const auto Hp = projectForce(b, ctx.kernel(j), F, fmt::format("H_{}", col));
        for(int e = 0; e < mp.nv; ++e) put(col, mp.vIndex + e, Hp[static_cast<std::size_t>(e)]);
      }
    }
  });
  return H;
}

} // namespace

std::vector<int> dofParents(const RobotModel & rm)
{
  std::vector<int> lambda(static_cast<std::size_t>(rm.nv), -1);
  for(const MovingJoint & mj : rm.joints)
  {
    const int first = mj.vIndex;
    lambda[static_cast<std::size_t>(first)] =
        mj.parent < 0 ? -1 : rm.joints[static_cast<std::size_t>(mj.parent)].vIndex + rm.joints[static_cast<std::size_t>(mj.parent)].nv - 1;
    for(int d = 1; d < mj.nv; ++d) lambda[static_cast<std::size_t>(first + d)] = first + d - 1;
  }
  return lambda;
}

std::vector<std::vector<Scalar>> emitMassMatrix(Block & b, const RobotModel & rm, const std::vector<double> & armature,
                                                const std::function<void(int r, int c, const Scalar & x)> & entry)
{
  PassContext ctx(b, rm);
  // A large tree's composite inertias are too many live values to read from the shared struct
  // after the pass: computed in place, each next to the columns that read it.
  if(SharedPasses::largeTree(rm)) ctx.emitInPlace();
  // Symmetric view L[r][c], c <= r (every entry emitCrba sets is in the lower triangle); H_ii += armature_i.
  auto L = emitCrba(ctx, [&](int r, int c, Scalar & x) {
    const auto i = static_cast<std::size_t>(r);
    if(r == c && i < armature.size() && armature[i] != 0.0)
      x = b.sum({Term{1.0, {x}}, Term{armature[i], {}}}, fmt::format("Ha{}", i));
    if(entry) entry(r, c, x);
  });
  return L;
}

namespace
{

/// From this many dofs on, emitLtdl factorises in an array rather than in named values (solo12 +
/// free base, 18 dofs: forward_dynamics_derivatives the same either way, within 3 %; from 16 on, the
/// quadruped's tests, packs included, run it).
constexpr std::size_t kLtdlArrayDofs = 16;

/// emitLtdl in an array (S ltdl[], kept in memory: RBDGEN_IN_MEMORY): row k holds H(k, j) for
/// the dofs j of k's path at depth(j), so for an ancestor i of k the entries over i's path are the
/// first depth(i) + 1 of both rows and Featherstone's update H(i, j) -= a H(k, j) is one
/// detail::minus_scaled over them. The same operations as in named values, where the entries of
/// H and their updates were spilled to the stack one by one (talos_reduced + free base: 2,851 of
/// the factorisation's 5,387 instructions, clang++; its forward_dynamics_derivatives 2.6-3.3 %
/// faster with clang++, 4.4-4.6 % with g++, outputs bitwise equal).
Ltdl emitLtdlInArray(Block & b, const std::vector<int> & lambda, std::vector<std::vector<Scalar>> H)
{
  const std::size_t nv = lambda.size();
  std::vector<std::size_t> depth(nv), off(nv);
  std::size_t size = 0;
  for(std::size_t k = 0; k < nv; ++k)
  {
    depth[k] = lambda[k] < 0 ? 0 : depth[static_cast<std::size_t>(lambda[k])] + 1;
    off[k] = size;
    size += depth[k] + 1;
  }
  b.comment("tree-sparse factorisation H = L^T D L (Featherstone, RBDA 6.5), in place in ltdl: row k holds H(k, j) for the dofs j "
            "of k's path at depth(j)");
  b.line(fmt::format("S ltdl[{}], ltdl_invD[{}];", size, nv));
  b.line("RBDGEN_IN_MEMORY(ltdl);");
  // H's entries computed into their slots (HomeInSlots.h; a value read again after the
  // factorisation has begun keeps its name): copied from named values instead, clang++ ran the
  // factorisation ~2 % slower, g++ ~1.5 %
  b.homeCopiesIn("ltdl", false, true);
  for(std::size_t k = 0; k < nv; ++k)
    for(int j = static_cast<int>(k); j >= 0; j = lambda[static_cast<std::size_t>(j)])
      b.line(fmt::format("ltdl[{}] = {};", off[k] + depth[static_cast<std::size_t>(j)], Block::text(H[k][static_cast<std::size_t>(j)])));
  Ltdl f{std::vector<std::vector<Scalar>>(nv, std::vector<Scalar>(nv)), std::vector<Scalar>(nv), lambda};
  for(std::size_t k = nv; k-- > 0;)
  {
    b.line(fmt::format("ltdl_invD[{}] = S(1) / ltdl[{}];", k, off[k] + depth[k]));
    f.invD[k] = Scalar::var(fmt::format("ltdl_invD[{}]", k));
    // for each ancestor i, the parent first: a = H(k, i) / D_k; H(i, j) -= a H(k, j) over the
    // dofs j of i's path; L(k, i) = a
    for(int i = lambda[k]; i >= 0; i = lambda[static_cast<std::size_t>(i)])
    {
      const auto ii = static_cast<std::size_t>(i);
      const std::size_t ki = off[k] + depth[ii];
      b.line(fmt::format("{{ const S a = ltdl[{0}] * ltdl_invD[{1}]; detail::minus_scaled<{2}>(ltdl + {3}, a, ltdl + {4}); ltdl[{0}] = a; }}",
                         ki, k, depth[ii] + 1, off[ii], off[k]));
      f.L[k][ii] = Scalar::var(fmt::format("ltdl[{}]", ki));
    }
  }
  return f;
}

} // namespace

Ltdl emitLtdl(Block & b, const RobotModel & rm, std::vector<std::vector<Scalar>> L)
{
  const auto nv = static_cast<std::size_t>(rm.nv);
  const std::vector<int> lambda = dofParents(rm);
  if(nv >= kLtdlArrayDofs) return emitLtdlInArray(b, lambda, std::move(L));
  b.comment("tree-sparse factorisation H = L^T D L (Featherstone, RBDA 6.5), in place on the lower triangle");
  std::vector<Scalar> invD(nv);
  for(std::size_t k = nv; k-- > 0;)
  {
    invD[k] = b.def("S(1) / " + Block::text(L[k][k]), fmt::format("invD{}", k));
    for(int i = lambda[k]; i >= 0; i = lambda[static_cast<std::size_t>(i)])
    {
      const auto ii = static_cast<std::size_t>(i);
      const Scalar a = mul(b, L[k][ii], invD[k], fmt::format("L{}_{}", k, i));
      for(int j = i; j >= 0; j = lambda[static_cast<std::size_t>(j)])
      {
        const auto jj = static_cast<std::size_t>(j);
        L[ii][jj] = b.sum({Term{1.0, {L[ii][jj]}}, Term{-1.0, {L[k][jj], a}}}, fmt::format("H{}_{}", i, j));
      }
      L[k][ii] = a;
    }
  }
  return {std::move(L), std::move(invD), lambda};
}

std::vector<Scalar> emitLtdlSolve(Block & b, const Ltdl & f, std::vector<Scalar> x)
{
  const std::size_t nv = x.size();
  const auto & L = f.L;
  const auto & lambda = f.lambda;
  b.comment("solve L^T D L x = rhs");
  for(std::size_t i = nv; i-- > 0;)
    for(int j = lambda[i]; j >= 0; j = lambda[static_cast<std::size_t>(j)])
    {
      const auto jj = static_cast<std::size_t>(j);
      x[jj] = b.sum({Term{1.0, {x[jj]}}, Term{-1.0, {L[i][jj], x[i]}}}, fmt::format("x{}", j));
    }
  for(std::size_t i = 0; i < nv; ++i) x[i] = mul(b, x[i], f.invD[i], fmt::format("x{}", i));
  // x_i -= L(i, j) x_j over i's ancestors j, the root's first and the parent's last: x_i then waits
  // on x_parent for one multiply-add, the older ancestors' terms summed before it is known (parent
  // first, each dof's whole sum waited on its parent: talos_reduced's arms chain ~16 of them a dof)
  for(std::size_t i = 0; i < nv; ++i)
    for(const std::size_t j : f.ancestorsRootFirst(i)) x[i] = b.sum({Term{1.0, {x[i]}}, Term{-1.0, {L[i][j], x[j]}}}, fmt::format("x{}", i));
  return x;
}

std::vector<std::size_t> Ltdl::ancestorsRootFirst(std::size_t i) const
{
  std::vector<std::size_t> path;
  for(int j = lambda[i]; j >= 0; j = lambda[static_cast<std::size_t>(j)]) path.push_back(static_cast<std::size_t>(j));
  std::reverse(path.begin(), path.end());
  return path;
}

MassMatrixLower massMatrixLowerBody(const RobotModel & rm, const std::vector<double> & armature)
{
  Block b;
  // put(r, c, H_rc) as soon as the entry is computed: its value is not kept live to the end
  const auto L = emitMassMatrix(b, rm, armature, [&b](int r, int c, const Scalar & x) {
    if(!x.isZero()) b.line(fmt::format("put({}, {}, {});", r, c, Block::text(x)));
  });
  MassMatrixLower out;
  std::vector<std::vector<int>> slot(static_cast<std::size_t>(rm.nv), std::vector<int>(static_cast<std::size_t>(rm.nv), -1));
  for(int r = 0; r < rm.nv; ++r)
    for(int c = 0; c <= r; ++c)
    {
      if(L[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)].isZero()) continue;
      slot[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = slot[static_cast<std::size_t>(c)][static_cast<std::size_t>(r)] = out.nnz++;
    }
  out.body = finish(b);
  for(int r = 0; r < rm.nv; ++r)
  {
    std::string row;
    for(int s : slot[static_cast<std::size_t>(r)]) row += (row.empty() ? "" : ", ") + std::to_string(s);
    out.slots += fmt::format("    {}, // row {}\n", row, r);
  }
  for(int r = 0; r < rm.nv; ++r)
  {
    std::string row;
    int n = 0;
    for(int c = 0; c <= r; ++c)
    {
      if(slot[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] < 0) continue;
      if(n > 0 && n % 10 == 0) row += "\n   ";
      row += fmt::format(" {{{}, {}}},", r, c);
      ++n;
    }
    if(n > 0) out.entries += "   " + row + "\n";
  }
  out.entries = out.entries.empty() ? "{}" : "{{\n" + out.entries + "}}";
  return out;
}

std::string massMatrixPackedText(const MassMatrixLower * sparse, int nv)
{
  const std::string text = selectSections(templateText("mass_matrix_packed.hpp.in"), {{"sparse", sparse != nullptr}},
                                          "templates/mass_matrix_packed.hpp.in");
  if(!sparse) return fillTemplate(text, {}, "templates/mass_matrix_packed.hpp.in");
  return fillTemplate(text,
                      {{"nnz", std::to_string(sparse->nnz)}, {"nv2", std::to_string(nv * nv)}, {"entries", sparse->entries}},
                      "templates/mass_matrix_packed.hpp.in");
}

EmittedBody forwardDynamicsBody(const RobotModel & rm, const FdOptions & opt)
{
  Block b;
  const auto nv = static_cast<std::size_t>(rm.nv);
  // With massMatrixLower, the columns go to a scratch block: only H's constant entries are kept.
  Block columns;
  std::vector<std::vector<Scalar>> L = emitMassMatrix(opt.massMatrixLower ? columns : b, rm, opt.armature);
  if(opt.massMatrixLower)
  {
    // H's entries from the header's mass_matrix_lower, slot by slot as massMatrixLowerBody numbers them
    b.line("S Hl[detail::mass_matrix_nnz];");
    b.line("detail::mass_matrix_lower<S>(q, [&Hl](int r, int c, const S & x) RBDGEN_INLINE_LAMBDA { "
           "Hl[detail::mass_matrix_slot[static_cast<std::size_t>(r * nv + c)]] = x; });");
    int slot = 0;
    for(std::size_t r = 0; r < nv; ++r)
      for(std::size_t c = 0; c <= r; ++c)
      {
        if(L[r][c].isZero()) continue;
        if(!L[r][c].isConst()) L[r][c] = Scalar::var(fmt::format("Hl[{}]", slot));
        ++slot;
      }
  }
  // Right-hand side: tau - C.
  std::vector<Scalar> x(nv);
  if(opt.biasCall.empty())
    for(std::size_t i = 0; i < nv; ++i) x[i] = Scalar::var(fmt::format("tau[{}]", i));
  else
  {
    b.line("const Tangent<S> C = " + opt.biasCall + ";");
    for(std::size_t i = 0; i < nv; ++i) x[i] = b.sum({Term{1.0, {Scalar::var(fmt::format("tau[{}]", i))}}, Term{-1.0, {Scalar::var(fmt::format("C[{}]", i))}}}, fmt::format("x{}", i));
  }
  const Ltdl f = emitLtdl(b, rm, std::move(L));
  x = emitLtdlSolve(b, f, std::move(x));
  for(std::size_t i = 0; i < nv; ++i) b.line(fmt::format("alphaD[{}] = {};", i, Block::text(x[i])));
  return finish(b);
}

} // namespace rbdgen::emit
