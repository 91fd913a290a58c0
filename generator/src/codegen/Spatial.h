#pragma once
// Symbolic 3-vectors, 3x3 matrices and spatial quantities, with the operations of sva written on
// 3x3 blocks. Each operation emits the statements it needs into a Block; constant entries fold.
// Conventions are those of sva: X = (E, r) from A to B, motion [w; v], force [n; f].

#include <array>
#include <functional>
#include <string>

#include <Eigen/Core>

#include "Expr.h"

namespace rbdgen::cg
{

struct Vec3
{
  std::array<Scalar, 3> v;
  const Scalar & operator[](int i) const { return v[static_cast<std::size_t>(i)]; }
  Scalar & operator[](int i) { return v[static_cast<std::size_t>(i)]; }
  static Vec3 constant(const Eigen::Vector3d & c);
  static Vec3 zero() { return constant(Eigen::Vector3d::Zero()); }
  bool isZero() const { return v[0].isZero() && v[1].isZero() && v[2].isZero(); }
};

struct Mat3
{
  std::array<Scalar, 9> m; // row-major
  const Scalar & operator()(int r, int c) const { return m[static_cast<std::size_t>(3 * r + c)]; }
  Scalar & operator()(int r, int c) { return m[static_cast<std::size_t>(3 * r + c)]; }
  static Mat3 constant(const Eigen::Matrix3d & c);
  static Mat3 identity() { return constant(Eigen::Matrix3d::Identity()); }
  Mat3 transpose() const;
};

/// Plücker transform X = (E, r).
struct Xform
{
  Mat3 E;
  Vec3 r;
  static Xform identity() { return {Mat3::identity(), Vec3::zero()}; }
};

struct Motion
{
  Vec3 w, v;
  static Motion zero() { return {Vec3::zero(), Vec3::zero()}; }
};

struct Force
{
  Vec3 n, f;
  static Force zero() { return {Vec3::zero(), Vec3::zero()}; }
};

/// Rigid-body inertia rbi(m, h, I) at a body origin; I stored as the full symmetric 3x3.
struct Inertia
{
  Scalar m;
  Vec3 h;
  Mat3 I;
};

// --- 3D ---------------------------------------------------------------------------------------
Vec3 add(Block & b, const Vec3 & x, const Vec3 & y, const std::string & hint);
Vec3 sub(Block & b, const Vec3 & x, const Vec3 & y, const std::string & hint);
Vec3 scale(Block & b, const Scalar & s, const Vec3 & x, const std::string & hint);
Vec3 cross(Block & b, const Vec3 & x, const Vec3 & y, const std::string & hint);
Scalar dot(Block & b, const Vec3 & x, const Vec3 & y, const std::string & hint);
Vec3 mul(Block & b, const Mat3 & A, const Vec3 & x, const std::string & hint);  ///< A x
Vec3 tmul(Block & b, const Mat3 & A, const Vec3 & x, const std::string & hint); ///< A^T x
Mat3 mul(Block & b, const Mat3 & A, const Mat3 & B, const std::string & hint);  ///< A B
Mat3 tmul(Block & b, const Mat3 & A, const Mat3 & B, const std::string & hint); ///< A^T B
Mat3 add(Block & b, const Mat3 & A, const Mat3 & B, const std::string & hint);
/// Symmetric A + B (computes the upper triangle only).
Mat3 addSym(Block & b, const Mat3 & A, const Mat3 & B, const std::string & hint);
/// E^T A E for symmetric A (upper triangle computed, mirrored).
Mat3 congruenceT(Block & b, const Mat3 & E, const Mat3 & A, const std::string & hint);

// --- spatial (sva semantics) --------------------------------------------------------------------
/// X * m = [E w; E (v - r x w)]
Motion apply(Block & b, const Xform & X, const Motion & m, const std::string & hint);
/// X^-1 * m = [E^T w; E^T v + r x E^T w]
Motion invApply(Block & b, const Xform & X, const Motion & m, const std::string & hint);
/// X^T f = [E^T n + r x E^T f; E^T f]
Force transApply(Block & b, const Xform & X, const Force & f, const std::string & hint);
/// X^* f = [E (n - r x f); E f]
Force dualApply(Block & b, const Xform & X, const Force & f, const std::string & hint);
/// X1 * X2 = (E1 E2, r2 + E2^T r1)
Xform compose(Block & b, const Xform & X1, const Xform & X2, const std::string & hint);
Motion add(Block & b, const Motion & x, const Motion & y, const std::string & hint);
Force add(Block & b, const Force & x, const Force & y, const std::string & hint);
Force sub(Block & b, const Force & x, const Force & y, const std::string & hint);
/// m1 x m2 = [w1 x w2; w1 x v2 + v1 x w2]
Motion cross(Block & b, const Motion & m1, const Motion & m2, const std::string & hint);
/// m . f = w . n + v . f
Scalar dot(Block & b, const Motion & m, const Force & f, const std::string & hint);
/// m x* f = [w x n + v x f; w x f]
Force crossDual(Block & b, const Motion & m, const Force & f, const std::string & hint);
/// I m = [I w + h x v; m v - h x w]
Force apply(Block & b, const Inertia & I, const Motion & m, const std::string & hint);
/// The product of a matrix of the rigid-body-inertia layout with x: [A w + h x v; mass v - h x w]
/// (mass nullptr: no mass term, as for dI/dt); entry i of n and f named name("_n", i), name("_f", i).
Force applyRigidLayout(Block & b, const Mat3 & A, const Vec3 & h, const Scalar * mass, const Motion & x,
                       const std::function<std::string(const char *, int)> & name);
/// X^T I X (inertia in the predecessor frame of X)
Inertia transApply(Block & b, const Xform & X, const Inertia & I, const std::string & hint);
Inertia add(Block & b, const Inertia & x, const Inertia & y, const std::string & hint);

} // namespace rbdgen::cg
