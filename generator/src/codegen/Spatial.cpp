#include "Spatial.h"

namespace rbdgen::cg
{
namespace
{

const char * const kAxis[3] = {"x", "y", "z"};
std::string el(const std::string & hint, int i) { return hint + "_" + kAxis[i]; }
std::string el(const std::string & hint, int r, int c)
{
  return hint + "_" + std::to_string(r) + std::to_string(c);
}

} // namespace

Vec3 Vec3::constant(const Eigen::Vector3d & c)
{
  return {{Scalar::constant(c.x()), Scalar::constant(c.y()), Scalar::constant(c.z())}};
}

Mat3 Mat3::constant(const Eigen::Matrix3d & c)
{
  Mat3 M;
  for(int r = 0; r < 3; ++r)
    for(int k = 0; k < 3; ++k) M(r, k) = Scalar::constant(c(r, k));
  return M;
}

Mat3 Mat3::transpose() const
{
  Mat3 T;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) T(r, c) = (*this)(c, r);
  return T;
}

Vec3 add(Block & b, const Vec3 & x, const Vec3 & y, const std::string & hint)
{
  Vec3 o;
  for(int i = 0; i < 3; ++i) o[i] = add(b, x[i], y[i], el(hint, i));
  return o;
}

Vec3 sub(Block & b, const Vec3 & x, const Vec3 & y, const std::string & hint)
{
  Vec3 o;
  for(int i = 0; i < 3; ++i) o[i] = sub(b, x[i], y[i], el(hint, i));
  return o;
}

Vec3 scale(Block & b, const Scalar & s, const Vec3 & x, const std::string & hint)
{
  Vec3 o;
  for(int i = 0; i < 3; ++i) o[i] = mul(b, s, x[i], el(hint, i));
  return o;
}

Vec3 cross(Block & b, const Vec3 & x, const Vec3 & y, const std::string & hint)
{
  Vec3 o;
  for(int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    o[i] = b.sum({Term{1.0, {x[j], y[k]}}, Term{-1.0, {x[k], y[j]}}}, el(hint, i));
  }
  return o;
}

Scalar dot(Block & b, const Vec3 & x, const Vec3 & y, const std::string & hint)
{
  return b.sum({Term{1.0, {x[0], y[0]}}, Term{1.0, {x[1], y[1]}}, Term{1.0, {x[2], y[2]}}}, hint);
}

Vec3 mul(Block & b, const Mat3 & A, const Vec3 & x, const std::string & hint)
{
  Vec3 o;
  for(int i = 0; i < 3; ++i)
    o[i] = b.sum({Term{1.0, {A(i, 0), x[0]}}, Term{1.0, {A(i, 1), x[1]}}, Term{1.0, {A(i, 2), x[2]}}}, el(hint, i));
  return o;
}

Vec3 tmul(Block & b, const Mat3 & A, const Vec3 & x, const std::string & hint)
{
  return mul(b, A.transpose(), x, hint);
}

Mat3 mul(Block & b, const Mat3 & A, const Mat3 & B, const std::string & hint)
{
  Mat3 o;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c)
      o(r, c) = b.sum({Term{1.0, {A(r, 0), B(0, c)}}, Term{1.0, {A(r, 1), B(1, c)}}, Term{1.0, {A(r, 2), B(2, c)}}},
                      el(hint, r, c));
  return o;
}

Mat3 tmul(Block & b, const Mat3 & A, const Mat3 & B, const std::string & hint)
{
  return mul(b, A.transpose(), B, hint);
}

Mat3 add(Block & b, const Mat3 & A, const Mat3 & B, const std::string & hint)
{
  Mat3 o;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) o(r, c) = add(b, A(r, c), B(r, c), el(hint, r, c));
  return o;
}

Mat3 addSym(Block & b, const Mat3 & A, const Mat3 & B, const std::string & hint)
{
  Mat3 o;
  for(int r = 0; r < 3; ++r)
    for(int c = r; c < 3; ++c)
    {
      o(r, c) = add(b, A(r, c), B(r, c), el(hint, r, c));
      o(c, r) = o(r, c);
    }
  return o;
}

Mat3 congruenceT(Block & b, const Mat3 & E, const Mat3 & A, const std::string & hint)
{
  const Mat3 AE = mul(b, A, E, hint + "_AE");
  Mat3 o;
  for(int r = 0; r < 3; ++r)
    for(int c = r; c < 3; ++c)
    {
      o(r, c) = b.sum({Term{1.0, {E(0, r), AE(0, c)}}, Term{1.0, {E(1, r), AE(1, c)}}, Term{1.0, {E(2, r), AE(2, c)}}},
                      el(hint, r, c));
      o(c, r) = o(r, c);
    }
  return o;
}

Motion apply(Block & b, const Xform & X, const Motion & m, const std::string & hint)
{
  // [E w; E (v - r x w)]
  const Vec3 rxw = cross(b, X.r, m.w, hint + "_rxw");
  const Vec3 vl = sub(b, m.v, rxw, hint + "_vr");
  return {mul(b, X.E, m.w, hint + "_w"), mul(b, X.E, vl, hint + "_v")};
}

Motion invApply(Block & b, const Xform & X, const Motion & m, const std::string & hint)
{
  // [E^T w; E^T v + r x E^T w]
  const Vec3 w = tmul(b, X.E, m.w, hint + "_w");
  const Vec3 Etv = tmul(b, X.E, m.v, hint + "_Etv");
  return {w, add(b, Etv, cross(b, X.r, w, hint + "_rxw"), hint + "_v")};
}

Force transApply(Block & b, const Xform & X, const Force & f, const std::string & hint)
{
  // [E^T n + r x E^T f; E^T f]
  const Vec3 Etf = tmul(b, X.E, f.f, hint + "_f");
  const Vec3 Etn = tmul(b, X.E, f.n, hint + "_Etn");
  return {add(b, Etn, cross(b, X.r, Etf, hint + "_rxf"), hint + "_n"), Etf};
}

Force dualApply(Block & b, const Xform & X, const Force & f, const std::string & hint)
{
  // [E (n - r x f); E f]
  const Vec3 nr = sub(b, f.n, cross(b, X.r, f.f, hint + "_rxf"), hint + "_nr");
  return {mul(b, X.E, nr, hint + "_n"), mul(b, X.E, f.f, hint + "_f")};
}

Xform compose(Block & b, const Xform & X1, const Xform & X2, const std::string & hint)
{
  // (E1 E2, r2 + E2^T r1)
  return {mul(b, X1.E, X2.E, hint + "_E"), add(b, X2.r, tmul(b, X2.E, X1.r, hint + "_Etr"), hint + "_r")};
}

Motion add(Block & b, const Motion & x, const Motion & y, const std::string & hint)
{
  return {add(b, x.w, y.w, hint + "_w"), add(b, x.v, y.v, hint + "_v")};
}

Force add(Block & b, const Force & x, const Force & y, const std::string & hint)
{
  return {add(b, x.n, y.n, hint + "_n"), add(b, x.f, y.f, hint + "_f")};
}

Force sub(Block & b, const Force & x, const Force & y, const std::string & hint)
{
  return {sub(b, x.n, y.n, hint + "_n"), sub(b, x.f, y.f, hint + "_f")};
}

namespace
{

// x1 x y1 + x2 x y2 in one statement per component.
Vec3 cross2(Block & b, const Vec3 & x1, const Vec3 & y1, const Vec3 & x2, const Vec3 & y2, const std::string & hint)
{
  Vec3 o;
  for(int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    o[i] = b.sum({Term{1.0, {x1[j], y1[k]}}, Term{-1.0, {x1[k], y1[j]}}, Term{1.0, {x2[j], y2[k]}},
                  Term{-1.0, {x2[k], y2[j]}}},
                 el(hint, i));
  }
  return o;
}

} // namespace

Motion cross(Block & b, const Motion & m1, const Motion & m2, const std::string & hint)
{
  return {cross(b, m1.w, m2.w, hint + "_w"), cross2(b, m1.w, m2.v, m1.v, m2.w, hint + "_v")};
}

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

Force crossDual(Block & b, const Motion & m, const Force & f, const std::string & hint)
{
  return {cross2(b, m.w, f.n, m.v, f.f, hint + "_n"), cross(b, m.w, f.f, hint + "_f")};
}

Force applyRigidLayout(Block & b, const Mat3 & A, const Vec3 & h, const Scalar * mass, const Motion & x,
                       const std::function<std::string(const char *, int)> & name)
{
  Force o;
  for(int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    o.n[i] = b.sum({Term{1.0, {A(i, 0), x.w[0]}}, Term{1.0, {A(i, 1), x.w[1]}}, Term{1.0, {A(i, 2), x.w[2]}},
                    Term{1.0, {h[j], x.v[k]}}, Term{-1.0, {h[k], x.v[j]}}},
                   name("_n", i));
    std::vector<Term> f{Term{-1.0, {h[j], x.w[k]}}, Term{1.0, {h[k], x.w[j]}}};
    if(mass) f.insert(f.begin(), Term{1.0, {*mass, x.v[i]}});
    o.f[i] = b.sum(f, name("_f", i));
  }
  return o;
}

Force apply(Block & b, const Inertia & I, const Motion & m, const std::string & hint)
{
  return applyRigidLayout(b, I.I, I.h, &I.m, m, [&](const char * part, int i) { return el(hint + part, i); });
}

Inertia transApply(Block & b, const Xform & X, const Inertia & I, const std::string & hint)
{
  // X^T rbi(m, h, I) X = rbi(m, a + m r, E^T I E - C) with a = E^T h and
  // C = r^ a^ + (a + m r)^ r^ = a r^T + r a^T + m r r^T - (2 r.a + m r.r) 1
  Inertia o;
  o.m = I.m;
  const Vec3 a = tmul(b, X.E, I.h, hint + "_Eth");
  const Vec3 mr = scale(b, I.m, X.r, hint + "_mr");
  o.h = add(b, a, mr, hint + "_h");
  const Mat3 EIE = congruenceT(b, X.E, I.I, hint + "_EIE");
  const Scalar ra = dot(b, X.r, a, hint + "_ra");
  const Scalar rmr = dot(b, X.r, mr, hint + "_rmr");
  for(int r = 0; r < 3; ++r)
    for(int c = r; c < 3; ++c)
    {
      std::vector<Term> t{Term{1.0, {EIE(r, c)}}, Term{-1.0, {a[r], X.r[c]}}, Term{-1.0, {X.r[r], a[c]}},
                          Term{-1.0, {X.r[r], mr[c]}}};
      if(r == c)
      {
        t.push_back(Term{2.0, {ra}});
        t.push_back(Term{1.0, {rmr}});
      }
      o.I(r, c) = b.sum(t, el(hint + "_I", r, c));
      o.I(c, r) = o.I(r, c);
    }
  return o;
}

Inertia add(Block & b, const Inertia & x, const Inertia & y, const std::string & hint)
{
  return {add(b, x.m, y.m, hint + "_m"), add(b, x.h, y.h, hint + "_h"), addSym(b, x.I, y.I, hint + "_I")};
}

} // namespace rbdgen::cg
