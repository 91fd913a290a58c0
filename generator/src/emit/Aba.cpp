// Articulated-body algorithm (Featherstone, RBDA table 7.1) on symbols: the forward-dynamics
// alternative to CRBA + LTDL. Articulated inertias are symmetric 6x6 [I H; H^T M] (sva::ABInertia).
#include <fmt/format.h>

#include "../passes/ArticulatedInertia.h"
#include "../passes/BackwardForce.h"
#include "Functions.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

EmittedBody abaBody(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm);
  const std::size_t n = rm.joints.size();
  std::vector<JointKernel> K;
  for(std::size_t k = 0; k < n; ++k) K.push_back(ctx.kernel(static_cast<int>(k)));
  std::vector<Motion> c(n);
  std::vector<ABI> IA(n);
  // Pass 1: v = X v_p + S alpha (forward motion pass), pA = v x* I v (inertial forces at a = 0),
  // c = v x S alpha, IA = I.
  // (each joint's pA and c right after its velocity: fewer values live at once)
  std::vector<Force> pA(n);
  forwardMotion(ctx, MotionRequest::make(false, true, false), ctx.allJoints(), [&](int k, const MotionState & m) {
    const auto kk = static_cast<std::size_t>(k);
    pA[kk] = inertialForce(ctx, m, true, k);
    c[kk] = velocityProduct(ctx, m, k, rm.joints[kk].tag + "_c");
    IA[kk] = fromRigid(bodyInertia(rm.joints[kk]));
  });
  // Pass 2 (leaves to root): U = IA S, D = S^T U, u = tau - S^T pA,
  // Ia = IA - U D^-1 U^T, pa = pA + Ia c + U D^-1 u; IA_p += X^T Ia X, pA_p += X^T pa.
  std::vector<std::vector<Force>> U(n);
  std::vector<std::vector<Scalar>> u(n);
  std::vector<DenseLdlt> Dfact;
  Dfact.reserve(n);
  std::vector<int> factIndex(n, -1);
  for(std::size_t k = n; k-- > 0;)
  {
    const MovingJoint & mj = rm.joints[k];
    const std::string t = mj.tag;
    b.comment(fmt::format("{} pass 2: articulated inertia and bias force", t));
    const auto nd = static_cast<std::size_t>(mj.nv);
    for(std::size_t d = 0; d < nd; ++d) U[k].push_back(applyABI(b, IA[k], K[k].S[d], fmt::format("{}_U{}", t, d)));
    std::vector<std::vector<Scalar>> D(nd, std::vector<Scalar>(nd));
    for(std::size_t r = 0; r < nd; ++r)
      for(std::size_t s = 0; s <= r; ++s) D[r][s] = D[s][r] = dot(b, K[k].S[r], U[k][s], fmt::format("{}_Dm{}{}", t, r, s));
    for(std::size_t d = 0; d < nd; ++d)
      u[k].push_back(b.sum({Term{1.0, {Scalar::var(fmt::format("tau[{}]", mj.vIndex + static_cast<int>(d)))}},
                            Term{-1.0, {dot(b, K[k].S[d], pA[k], fmt::format("{}_SpA{}", t, d))}}},
                           fmt::format("{}_u{}", t, d)));
    factIndex[k] = static_cast<int>(Dfact.size());
    Dfact.emplace_back(b, D, t + "_D");
    if(mj.parent < 0) continue;
    const DenseLdlt & F = Dfact.back();
    // W = U D^-1 (one row of D^-1 U^T per component), Dinv u
    std::vector<std::vector<Scalar>> W(6, std::vector<Scalar>(nd));
    for(int comp = 0; comp < 6; ++comp)
    {
      std::vector<Scalar> rhs(nd);
      for(std::size_t d = 0; d < nd; ++d) rhs[d] = comp < 3 ? U[k][d].n[comp] : U[k][d].f[comp - 3];
      const auto sol = F.solve(b, rhs, fmt::format("{}_W{}", t, comp));
      for(std::size_t d = 0; d < nd; ++d) W[static_cast<std::size_t>(comp)][d] = sol[d];
    }
    const auto Du = F.solve(b, u[k], t + "_Du");
    auto Ucomp = [&](std::size_t d, int comp) { return comp < 3 ? U[k][d].n[comp] : U[k][d].f[comp - 3]; };
    // Ia = IA - W U^T (symmetric)
    ABI Ia = IA[k];
    auto entry = [&](const ABI & A, int r, int s) -> Scalar {
      if(r < 3 && s < 3) return A.I(r, s);
      if(r < 3) return A.H(r, s - 3);
      if(s < 3) return A.H(s, r - 3);
      return A.M(r - 3, s - 3);
    };
    for(int r = 0; r < 6; ++r)
      for(int s = r; s < 6; ++s)
      {
        std::vector<Term> tt{Term{1.0, {entry(IA[k], r, s)}}};
        for(std::size_t d = 0; d < nd; ++d) tt.push_back(Term{-1.0, {W[static_cast<std::size_t>(r)][d], Ucomp(d, s)}});
        const Scalar x = b.sum(tt, fmt::format("{}_Ia{}{}", t, r, s));
        if(r < 3 && s < 3) Ia.I(r, s) = Ia.I(s, r) = x;
        else if(r < 3) Ia.H(r, s - 3) = x;
        else Ia.M(r - 3, s - 3) = Ia.M(s - 3, r - 3) = x;
      }
    // pa = pA + Ia c + U Dinv u
    const Force Iac = applyABI(b, Ia, c[k], t + "_Iac");
    Force pa;
    for(int i = 0; i < 3; ++i)
    {
      std::vector<Term> tn{Term{1.0, {pA[k].n[i]}}, Term{1.0, {Iac.n[i]}}}, tf{Term{1.0, {pA[k].f[i]}}, Term{1.0, {Iac.f[i]}}};
      for(std::size_t d = 0; d < nd; ++d)
      {
        tn.push_back(Term{1.0, {U[k][d].n[i], Du[d]}});
        tf.push_back(Term{1.0, {U[k][d].f[i], Du[d]}});
      }
      pa.n[i] = b.sum(tn, fmt::format("{}_pa_n{}", t, i));
      pa.f[i] = b.sum(tf, fmt::format("{}_pa_f{}", t, i));
    }
    const auto p = static_cast<std::size_t>(mj.parent);
    const ABI IaP = transApplyABI(b, treeXform(mj), transApplyABI(b, K[k].Xj, Ia, t + "_IaJ"), t + "_IaP");
    IA[p] = addABI(b, IA[p], IaP, rm.joints[p].tag + "_IA");
    pA[p] = add(b, pA[p], toParent(b, mj, K[k], pa, t + "_paP"), rm.joints[p].tag + "_pA");
  }
  // Pass 3 (root to leaves): a' = X a_p + c, alphaD = D^-1 (u - U^T a'), a = a' + S alphaD.
  Motion a0 = Motion::zero();
  a0.v[2] = Scalar::constant(9.81); // gravity as an upward acceleration of the world
  std::vector<Motion> a(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    const std::string t = mj.tag;
    b.comment(fmt::format("{} pass 3: accelerations", t));
    const Motion ap = mj.parent < 0 ? a0 : a[static_cast<std::size_t>(mj.parent)];
    const Motion a1 = add(b, toChild(b, mj, K[k], ap, t + "_Xa"), c[k], t + "_a1");
    const auto nd = static_cast<std::size_t>(mj.nv);
    std::vector<Scalar> rhs(nd);
    for(std::size_t d = 0; d < nd; ++d)
      rhs[d] = b.sum({Term{1.0, {u[k][d]}}, Term{-1.0, {dot(b, a1, U[k][d], fmt::format("{}_Ua{}", t, d))}}},
                     fmt::format("{}_r{}", t, d));
    const auto qdd = Dfact[static_cast<std::size_t>(factIndex[k])].solve(b, rhs, t + "_qdd");
    Motion sa = a1;
    for(std::size_t d = 0; d < nd; ++d)
    {
      b.line(fmt::format("alphaD[{}] = {};", mj.vIndex + static_cast<int>(d), Block::text(qdd[d])));
      for(int i = 0; i < 3; ++i)
      {
        sa.w[i] = b.sum({Term{1.0, {sa.w[i]}}, Term{1.0, {K[k].S[d].w[i], qdd[d]}}}, fmt::format("{}_a_w{}", t, i));
        sa.v[i] = b.sum({Term{1.0, {sa.v[i]}}, Term{1.0, {K[k].S[d].v[i], qdd[d]}}}, fmt::format("{}_a_v{}", t, i));
      }
    }
    a[k] = sa;
  }
  return finish(b);
}

} // namespace rbdgen::emit
