#include "JointKernels.h"
#include "BackwardForce.h"

#include <cmath>

#include <fmt/format.h>

namespace rbdgen::passes
{

Xform constantXform(const sva::PTransformd & X)
{
  return {Mat3::constant(X.rotation()), Vec3::constant(X.translation())};
}

namespace
{

Xform namedXform(const sva::PTransformd & X, const std::string & c)
{
  Xform o;
  for(int r = 0; r < 3; ++r)
  {
    for(int k = 0; k < 3; ++k) o.E(r, k) = Scalar::named(X.rotation()(r, k), fmt::format("{}.E{}{}", c, r, k));
    o.r[r] = Scalar::named(X.translation()[r], fmt::format("{}.r{}", c, "xyz"[r]));
  }
  return o;
}

// "a, b, c" of the values (no braces: the model structs are flat, one member per entry)
std::string numbers(const std::vector<double> & values)
{
  std::string out;
  for(double v : values) out += (out.empty() ? "" : ", ") + Block::number(v);
  return out;
}

std::string numbers(const Eigen::Vector3d & v) { return numbers(std::vector<double>{v.x(), v.y(), v.z()}); }

std::string numbers(const Eigen::Matrix3d & M) // row by row
{
  return numbers(std::vector<double>{M(0, 0), M(0, 1), M(0, 2), M(1, 0), M(1, 1), M(1, 2), M(2, 0), M(2, 1), M(2, 2)});
}

} // namespace

Xform treeXform(const MovingJoint & mj)
{
  return namedXform(mj.Xt, "model::" + mj.tag);
}

Xform linkXform(const BodyFrame & bf)
{
  return bf.atOwnerFrame() ? constantXform(bf.X_owner_link) : namedXform(bf.X_owner_link, "model::L_" + bf.ident);
}

std::string modelConstants(const RobotModel & rm)
{
  std::string out;
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    std::string moved;
    for(const BodyFrame & bf : rm.bodies)
      if(bf.owner == static_cast<int>(k))
      {
        moved = bf.name;
        break;
      }
    out += fmt::format("constexpr JointConstants {} = {{{{/*E*/ {}, /*r*/ {}}}, /*m*/ {}, /*h*/ {}, /*I*/ {}}}; // joint '{}', moving link '{}'\n", mj.tag,
                       numbers(Eigen::Matrix3d(mj.Xt.rotation())), numbers(Eigen::Vector3d(mj.Xt.translation())),
                       Block::number(mj.inertia.mass()), numbers(Eigen::Vector3d(mj.inertia.momentum())),
                       numbers(symmetricInertia(mj)), mj.name, moved);
  }
  for(const BodyFrame & bf : rm.bodies)
    if(!bf.atOwnerFrame())
      out += fmt::format("constexpr LinkConstants L_{} = {{/*E*/ {}, /*r*/ {}}}; // link '{}' on {}\n", bf.ident,
                         numbers(Eigen::Matrix3d(bf.X_owner_link.rotation())), numbers(Eigen::Vector3d(bf.X_owner_link.translation())),
                         bf.name, bf.owner < 0 ? "the world" : "joint '" + rm.joints[static_cast<std::size_t>(bf.owner)].name + "'");
  return out;
}

namespace
{

std::string qAt(const std::string & q, int i)
{
  return fmt::format("{}[{}]", q, i);
}

// E = R(a, θ)^T = c 1 - s a^ + (1 - c) a a^T, with transposed = R(a, θ) for backward joints.
Mat3 axisRotationT(Block & b, const Eigen::Vector3d & a, const Scalar & c, const Scalar & s, bool transposed,
                   const std::string & hint)
{
  Eigen::Matrix3d ax;
  ax << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  const Eigen::Matrix3d aa = a * a.transpose();
  const double sign = transposed ? 1.0 : -1.0;
  Mat3 E;
  for(int r = 0; r < 3; ++r)
    for(int k = 0; k < 3; ++k)
    {
      const double delta = r == k ? 1.0 : 0.0;
      // c (δ - a_r a_k) + a_r a_k ± s (a^)_rk
      E(r, k) = b.sum({Term{delta - aa(r, k), {c}}, Term{sign * ax(r, k), {s}}, Term{aa(r, k), {}}},
                      fmt::format("{}_E{}{}", hint, r, k));
    }
  return E;
}

// E = R(quat)^T for a quaternion [w x y z] that need not be unit: R = 1 + s (w v^ + v^ v^) with
// s = 2 / |quat|^2, the rotation of the normalised quaternion.
Mat3 quaternionRotationT(Block & b, const std::string & q, int i0, const std::string & hint)
{
  const Scalar w = Scalar::var(qAt(q, i0)), x = Scalar::var(qAt(q, i0 + 1)), y = Scalar::var(qAt(q, i0 + 2)),
               z = Scalar::var(qAt(q, i0 + 3));
  const Scalar n2 = b.sum({Term{1, {w, w}}, Term{1, {x, x}}, Term{1, {y, y}}, Term{1, {z, z}}}, hint + "_n2");
  const Scalar s = b.def("S(2) / " + Block::text(n2), hint + "_s");
  auto p = [&](const Scalar & u, const Scalar & v, const std::string & name) {
    return b.sum({Term{1, {s, u, v}}}, hint + "_" + name);
  };
  const Scalar xx = p(x, x, "xx"), yy = p(y, y, "yy"), zz = p(z, z, "zz"), xy = p(x, y, "xy"), xz = p(x, z, "xz"),
               yz = p(y, z, "yz"), wx = p(w, x, "wx"), wy = p(w, y, "wy"), wz = p(w, z, "wz");
  auto e = [&](std::vector<Term> t, int r, int c) { return b.sum(t, fmt::format("{}_E{}{}", hint, r, c)); };
  // R (right-handed, rotation of the child in the parent); E = R^T.
  Mat3 R;
  R(0, 0) = e({Term{1, {}}, Term{-1, {yy}}, Term{-1, {zz}}}, 0, 0);
  R(1, 1) = e({Term{1, {}}, Term{-1, {xx}}, Term{-1, {zz}}}, 1, 1);
  R(2, 2) = e({Term{1, {}}, Term{-1, {xx}}, Term{-1, {yy}}}, 2, 2);
  // Off-diagonal entries named after their place in E = R^T.
  R(0, 1) = e({Term{1, {xy}}, Term{-1, {wz}}}, 1, 0);
  R(1, 0) = e({Term{1, {xy}}, Term{1, {wz}}}, 0, 1);
  R(0, 2) = e({Term{1, {xz}}, Term{1, {wy}}}, 2, 0);
  R(2, 0) = e({Term{1, {xz}}, Term{-1, {wy}}}, 0, 2);
  R(1, 2) = e({Term{1, {yz}}, Term{-1, {wx}}}, 2, 1);
  R(2, 1) = e({Term{1, {yz}}, Term{1, {wx}}}, 1, 2);
  return R.transpose();
}

Motion constantMotion(const Eigen::Matrix<double, 6, 1> & s)
{
  return {Vec3::constant(s.head<3>()), Vec3::constant(s.tail<3>())};
}

} // namespace

JointKernel emitJointKernel(Block & b, const MovingJoint & mj, const std::string & q, const AngleSinCos & angles)
{
  const rbd::Joint & j = mj.joint;
  const std::string h = mj.tag;
  const bool fwd = j.forward();
  const Eigen::Vector3d a = j.axis();
  JointKernel K;
  K.Xj = Xform::identity();
  auto sincos = [&](int i) {
    if(angles) return angles(i);
    const Scalar s = b.def(fmt::format("std::sin({})", qAt(q, i)), h + "_s");
    const Scalar c = b.def(fmt::format("std::cos({})", qAt(q, i)), h + "_c");
    return std::make_pair(s, c);
  };
  // Forward kernel; backward joints are handled below.
  switch(j.type())
  {
    case rbd::Joint::Rev:
    {
      const auto [s, c] = sincos(mj.qIndex);
      // Backward Rev: X_fwd(-q) = rotation transposed.
      K.Xj.E = axisRotationT(b, a, c, s, !fwd, h);
      break;
    }
    case rbd::Joint::Prism:
      K.Xj.r = scale(b, Scalar::var(qAt(q, mj.qIndex)), Vec3::constant(fwd ? a : Eigen::Vector3d(-a)), h + "_r");
      break;
    case rbd::Joint::Cylindrical:
    {
      const auto [s, c] = sincos(mj.qIndex);
      K.Xj.E = axisRotationT(b, a, c, s, !fwd, h);
      K.Xj.r = scale(b, Scalar::var(qAt(q, mj.qIndex + 1)), Vec3::constant(fwd ? a : Eigen::Vector3d(-a)), h + "_r");
      break;
    }
    case rbd::Joint::Planar:
    {
      const auto [s, c] = sincos(mj.qIndex);
      K.Xj.E = axisRotationT(b, a, c, s, false, h);
      // r = R(n, θ) (x u + y w) = (c x − s y) u + (s x + c y) w   (RBDyn: (x, y) in successor axes)
      const Scalar x = Scalar::var(qAt(q, mj.qIndex + 1)), y = Scalar::var(qAt(q, mj.qIndex + 2));
      const Scalar ru = b.sum({Term{1, {c, x}}, Term{-1, {s, y}}}, h + "_ru");
      const Scalar rw = b.sum({Term{1, {s, x}}, Term{1, {c, y}}}, h + "_rw");
      const Eigen::Vector3d u = j.planeU(), w = j.planeW();
      for(int i = 0; i < 3; ++i) K.Xj.r[i] = b.sum({Term{u(i), {ru}}, Term{w(i), {rw}}}, fmt::format("{}_r{}", h, i));
      break;
    }
    case rbd::Joint::Spherical:
      K.Xj.E = quaternionRotationT(b, q, mj.qIndex, h);
      break;
    case rbd::Joint::Free:
      K.Xj.E = quaternionRotationT(b, q, mj.qIndex, h);
      for(int i = 0; i < 3; ++i) K.Xj.r[i] = Scalar::var(qAt(q, mj.qIndex + 4 + i));
      break;
    case rbd::Joint::Fixed:
      break;
  }
  const auto & S = j.forwardMotionSubspace();
  const bool axisJoint = j.type() == rbd::Joint::Rev || j.type() == rbd::Joint::Prism || j.type() == rbd::Joint::Cylindrical;
  if(fwd || axisJoint)
  {
    for(int d = 0; d < mj.nv; ++d) K.S.push_back(constantMotion(fwd ? S.col(d) : Eigen::Matrix<double, 6, 1>(-S.col(d))));
    return K;
  }
  // Backward Spherical/Planar/Free: X = X_fwd^-1 = (E^T, -E r), S = -X_fwd^-1 S_fwd.
  const Xform Xf = K.Xj;
  K.Xj.E = Xf.E.transpose();
  K.Xj.r = scale(b, Scalar::constant(-1.0), mul(b, Xf.E, Xf.r, h + "_Er"), h + "_rb");
  for(int d = 0; d < mj.nv; ++d)
  {
    const Motion col = invApply(b, Xf, constantMotion(S.col(d)), fmt::format("{}_S{}", h, d));
    K.S.push_back({scale(b, Scalar::constant(-1.0), col.w, fmt::format("{}_Sw{}", h, d)),
                   scale(b, Scalar::constant(-1.0), col.v, fmt::format("{}_Sv{}", h, d))});
  }
  return K;
}

Motion toChild(Block & b, const MovingJoint & mj, const JointKernel & K, const Motion & m, const std::string & hint)
{
  return apply(b, K.Xj, apply(b, treeXform(mj), m, hint + "_t"), hint);
}

Force toParent(Block & b, const MovingJoint & mj, const JointKernel & K, const Force & f, const std::string & hint)
{
  return transApply(b, treeXform(mj), transApply(b, K.Xj, f, hint + "_j"), hint);
}

Motion jointMotion(Block & b, const JointKernel & K, const std::string & v, int offset, const std::string & hint)
{
  Motion out;
  for(int i = 0; i < 3; ++i)
  {
    std::vector<Term> tw, tv;
    for(std::size_t d = 0; d < K.S.size(); ++d)
    {
      const Scalar x = Scalar::var(fmt::format("{}[{}]", v, offset + static_cast<int>(d)));
      tw.push_back(Term{1.0, {K.S[d].w[i], x}});
      tv.push_back(Term{1.0, {K.S[d].v[i], x}});
    }
    const char * ax = i == 0 ? "x" : (i == 1 ? "y" : "z");
    out.w[i] = b.sum(tw, hint + "_w_" + ax);
    out.v[i] = b.sum(tv, hint + "_v_" + ax);
  }
  return out;
}

std::vector<Scalar> projectForce(Block & b, const JointKernel & K, const Force & f, const std::string & hint)
{
  std::vector<Scalar> out;
  for(std::size_t d = 0; d < K.S.size(); ++d)
  {
    std::vector<Term> t;
    for(int i = 0; i < 3; ++i)
    {
      t.push_back(Term{1.0, {K.S[d].w[i], f.n[i]}});
      t.push_back(Term{1.0, {K.S[d].v[i], f.f[i]}});
    }
    out.push_back(b.sum(t, fmt::format("{}_{}", hint, d)));
  }
  return out;
}

std::string describeJoint(const MovingJoint & mj)
{
  const rbd::Joint & j = mj.joint;
  std::string s = rbd::jointTypeName(j.type());
  const bool hasAxis = j.type() == rbd::Joint::Rev || j.type() == rbd::Joint::Prism ||
                       j.type() == rbd::Joint::Cylindrical || j.type() == rbd::Joint::Planar;
  if(hasAxis)
  {
    const Eigen::Vector3d a = j.axis();
    const char * names[3] = {"x", "y", "z"};
    std::string ax;
    for(int i = 0; i < 3; ++i)
      if(std::abs(std::abs(a(i)) - 1.0) < 1e-15) ax = std::string(a(i) < 0 ? "-" : "") + names[i];
    s += ax.empty() ? fmt::format(" about ({:.6g}, {:.6g}, {:.6g})", a.x(), a.y(), a.z()) : " about " + ax;
  }
  if(!j.forward()) s += ", backward";
  return s;
}

} // namespace rbdgen::passes
