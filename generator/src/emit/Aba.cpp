// Articulated-body algorithm (Featherstone, RBDA table 7.1) on symbols: the forward-dynamics
// alternative to CRBA + LTDL. Articulated inertias are symmetric 6x6 [I H; H^T M] (sva::ABInertia).
#include <fmt/format.h>

#include "Functions.h"
#include "Kernels.h"

namespace rbdgen::emit
{
namespace
{

/// abi(M, H, I) = [I H; H^T M], I and M symmetric.
struct ABI
{
  Mat3 M, H, I;
};

ABI fromRigid(const Inertia & rb)
{
  // rbi(m, h, I) = [I h^; -h^ m1]
  ABI a;
  a.I = rb.I;
  a.M = Mat3::constant(Eigen::Matrix3d::Zero());
  a.H = Mat3::constant(Eigen::Matrix3d::Zero());
  for(int i = 0; i < 3; ++i) a.M(i, i) = rb.m;
  a.H(0, 1) = Scalar::constant(-rb.h[2].value());
  a.H(0, 2) = Scalar::constant(rb.h[1].value());
  a.H(1, 0) = Scalar::constant(rb.h[2].value());
  a.H(1, 2) = Scalar::constant(-rb.h[0].value());
  a.H(2, 0) = Scalar::constant(-rb.h[1].value());
  a.H(2, 1) = Scalar::constant(rb.h[0].value());
  return a;
}

/// A m = [I w + H v; H^T w + M v]
Force applyABI(Block & b, const ABI & A, const Motion & m, const std::string & hint)
{
  Force f;
  for(int i = 0; i < 3; ++i)
  {
    std::vector<Term> tn, tf;
    for(int k = 0; k < 3; ++k)
    {
      tn.push_back(Term{1.0, {A.I(i, k), m.w[k]}});
      tn.push_back(Term{1.0, {A.H(i, k), m.v[k]}});
      tf.push_back(Term{1.0, {A.H(k, i), m.w[k]}});
      tf.push_back(Term{1.0, {A.M(i, k), m.v[k]}});
    }
    const char * ax = i == 0 ? "x" : (i == 1 ? "y" : "z");
    f.n[i] = b.sum(tn, hint + "_n_" + ax);
    f.f[i] = b.sum(tf, hint + "_f_" + ax);
  }
  return f;
}

/// X^T A X: M' = E^T M E, H' = E^T H E + r^ M', I' = E^T I E + r^ (E^T H E)^T - H' r^
ABI transApplyABI(Block & b, const Xform & X, const ABI & A, const std::string & hint)
{
  ABI o;
  o.M = congruenceT(b, X.E, A.M, hint + "_M");
  const Mat3 EtHE = tmul(b, X.E, mul(b, A.H, X.E, hint + "_HE"), hint + "_EtHE");
  Mat3 rx = Mat3::constant(Eigen::Matrix3d::Zero());
  rx(0, 1) = neg(b, X.r[2], hint + "_rz");
  rx(0, 2) = X.r[1];
  rx(1, 0) = X.r[2];
  rx(1, 2) = neg(b, X.r[0], hint + "_rx");
  rx(2, 0) = neg(b, X.r[1], hint + "_ry");
  rx(2, 1) = X.r[0];
  o.H = add(b, EtHE, mul(b, rx, o.M, hint + "_rM"), hint + "_H");
  const Mat3 EIE = congruenceT(b, X.E, A.I, hint + "_EIE");
  // I' = EIE + r^ EtHE^T - H' r^ (symmetric: upper triangle, mirrored)
  for(int r = 0; r < 3; ++r)
    for(int c = r; c < 3; ++c)
    {
      std::vector<Term> t{Term{1.0, {EIE(r, c)}}};
      for(int k = 0; k < 3; ++k)
      {
        t.push_back(Term{1.0, {rx(r, k), EtHE(c, k)}});
        t.push_back(Term{-1.0, {o.H(r, k), rx(k, c)}});
      }
      o.I(r, c) = b.sum(t, fmt::format("{}_I{}{}", hint, r, c));
      o.I(c, r) = o.I(r, c);
    }
  return o;
}

ABI addABI(Block & b, const ABI & x, const ABI & y, const std::string & hint)
{
  return {addSym(b, x.M, y.M, hint + "_M"), add(b, x.H, y.H, hint + "_H"), addSym(b, x.I, y.I, hint + "_I")};
}

Scalar dotMF(Block & b, const Motion & m, const Force & f, const std::string & hint)
{
  std::vector<Term> t;
  for(int i = 0; i < 3; ++i)
  {
    t.push_back(Term{1.0, {m.w[i], f.n[i]}});
    t.push_back(Term{1.0, {m.v[i], f.f[i]}});
  }
  return b.sum(t, hint);
}

/// Dense symmetric positive-definite k x k system: L D L^T factorisation on symbols, then solves.
struct DenseLdlt
{
  std::vector<std::vector<Scalar>> L; // unit lower, below the diagonal
  std::vector<Scalar> invD;

  DenseLdlt(Block & b, std::vector<std::vector<Scalar>> A, const std::string & hint)
  {
    const std::size_t k = A.size();
    L.assign(k, std::vector<Scalar>(k, Scalar::constant(0)));
    invD.assign(k, Scalar::constant(0));
    std::vector<Scalar> D(k);
    for(std::size_t j = 0; j < k; ++j)
    {
      std::vector<Term> t{Term{1.0, {A[j][j]}}};
      for(std::size_t p = 0; p < j; ++p) t.push_back(Term{-1.0, {L[j][p], L[j][p], D[p]}});
      D[j] = b.sum(t, fmt::format("{}_D{}", hint, j));
      invD[j] = b.def("S(1) / " + Block::text(D[j]), fmt::format("{}_invD{}", hint, j));
      for(std::size_t i = j + 1; i < k; ++i)
      {
        std::vector<Term> u{Term{1.0, {A[i][j]}}};
        for(std::size_t p = 0; p < j; ++p) u.push_back(Term{-1.0, {L[i][p], L[j][p], D[p]}});
        L[i][j] = b.sum({Term{1.0, {b.sum(u, fmt::format("{}_N{}{}", hint, i, j)), invD[j]}}}, fmt::format("{}_L{}{}", hint, i, j));
      }
    }
  }

  std::vector<Scalar> solve(Block & b, std::vector<Scalar> x, const std::string & hint) const
  {
    const std::size_t k = x.size();
    for(std::size_t i = 0; i < k; ++i)
    {
      std::vector<Term> t{Term{1.0, {x[i]}}};
      for(std::size_t p = 0; p < i; ++p) t.push_back(Term{-1.0, {L[i][p], x[p]}});
      x[i] = b.sum(t, fmt::format("{}_y{}", hint, i));
    }
    for(std::size_t i = 0; i < k; ++i) x[i] = mul(b, x[i], invD[i], fmt::format("{}_z{}", hint, i));
    for(std::size_t i = k; i-- > 0;)
    {
      std::vector<Term> t{Term{1.0, {x[i]}}};
      for(std::size_t p = i + 1; p < k; ++p) t.push_back(Term{-1.0, {L[p][i], x[p]}});
      x[i] = b.sum(t, fmt::format("{}_x{}", hint, i));
    }
    return x;
  }
};

} // namespace

EmittedBody abaBody(const RobotModel & rm)
{
  Block b;
  const auto K = emitKernels(b, rm, "q");
  const std::size_t n = rm.joints.size();
  std::vector<Motion> v(n), c(n);
  std::vector<ABI> IA(n);
  std::vector<Force> pA(n);
  // Pass 1: v = X v_p + S alpha, c = v x S alpha, IA = I, pA = v x* I v.
  for(std::size_t k = 0; k < n; ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    const std::string t = mj.tag;
    b.comment(fmt::format("{} pass 1: velocity, bias acceleration, bias force", t));
    const Motion vJ = jointMotion(b, K[k], "alpha", mj.vIndex, t + "_vJ");
    const Motion vp = mj.parent < 0 ? Motion::zero() : v[static_cast<std::size_t>(mj.parent)];
    v[k] = add(b, toChild(b, mj, K[k], vp, t + "_Xv"), vJ, t + "_v");
    c[k] = cross(b, v[k], vJ, t + "_c");
    const Inertia I = constantInertia(mj.inertia.mass(), mj.inertia.momentum(), mj.inertia.inertia());
    IA[k] = fromRigid(I);
    pA[k] = crossDual(b, v[k], apply(b, I, v[k], t + "_Iv"), t + "_pA");
  }
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
      for(std::size_t s = 0; s <= r; ++s) D[r][s] = D[s][r] = dotMF(b, K[k].S[r], U[k][s], fmt::format("{}_Dm{}{}", t, r, s));
    for(std::size_t d = 0; d < nd; ++d)
      u[k].push_back(b.sum({Term{1.0, {Scalar::var(fmt::format("tau[{}]", mj.vIndex + static_cast<int>(d)))}},
                            Term{-1.0, {dotMF(b, K[k].S[d], pA[k], fmt::format("{}_SpA{}", t, d))}}},
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
    const ABI IaP = transApplyABI(b, constantXform(mj.Xt), transApplyABI(b, K[k].Xj, Ia, t + "_IaJ"), t + "_IaP");
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
      rhs[d] = b.sum({Term{1.0, {u[k][d]}}, Term{-1.0, {dotMF(b, a1, U[k][d], fmt::format("{}_Ua{}", t, d))}}},
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
