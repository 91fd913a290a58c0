#include "ArticulatedInertia.h"

#include <fmt/format.h>

namespace rbdgen::passes
{


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

DenseLdlt::DenseLdlt(Block & b, std::vector<std::vector<Scalar>> A, const std::string & hint)
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

std::vector<Scalar> DenseLdlt::solve(Block & b, std::vector<Scalar> x, const std::string & hint) const
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

} // namespace rbdgen::passes
