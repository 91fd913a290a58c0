// Link Jacobians along the support path of a link given at run time, from precomputed kinematics
// (leaf to root by direct jumps) or from q (one straight-line case per link, nothing computed off
// the path; Jdot alpha is computed from these columns by the header's detail::jdot_from_columns),
// and the Jacobian of the centre of mass.
#include <fmt/format.h>

#include "../passes/CompositeInertia.h"
#include "../passes/SupportPath.h"
#include "Functions.h"
#include "Outputs.h"

namespace rbdgen::emit
{

using namespace rbdgen::passes;

namespace
{

/// How a support-path column is stored in its 6-vector and moved to the point p (the template
/// argument of the header's detail::put_column).
enum class ColumnKind
{
  translation, ///< [0; u]: J = [0; u]
  rotation,    ///< [w; o], a rotation about an axis through o: J = [w; w x (p - o)]
  screw        ///< [w; u - w x o], the column at the world origin: J = [w; (u - w x o) + w x p]
};

bool isZero(const Vec3 & x)
{
  return x[0].isZero() && x[1].isZero() && x[2].isZero();
}

// Columns of joint k, world axes: w = R s_w, u = R s_v (R = E_0_k^T, o = o_k its origin), stored
// by kind (every entry, zeros too) into the 6-vectors col0, col1, ...: a rotation keeps its axis
// point o instead of its velocity at the world origin (-w x o, 9 operations a column: w x (p - o)
// at the end costs what w x p did, and p - o is shared by the joint's columns).
std::vector<ColumnKind> writeSupportColumns(Block & b, const JointKernel & K, const Xform & X0)
{
  std::vector<ColumnKind> kinds;
  for(std::size_t d = 0; d < K.S.size(); ++d)
  {
    const Motion & Sd = K.S[d];
    const std::string h = fmt::format("J_{}", d);
    const Vec3 w = tmul(b, X0.E, Sd.w, h + "_w");
    const ColumnKind kind = isZero(Sd.w) ? ColumnKind::translation : (isZero(Sd.v) ? ColumnKind::rotation : ColumnKind::screw);
    Vec3 second = X0.r; // (rotation)
    if(kind == ColumnKind::translation) second = tmul(b, X0.E, Sd.v, h + "_Rv");
    if(kind == ColumnKind::screw) second = sub(b, tmul(b, X0.E, Sd.v, h + "_Rv"), cross(b, w, X0.r, h + "_wxo"), h + "_u");
    b.line(fmt::format("detail::set_motion(col{}, {}, {}, {}, {}, {}, {});", d, Block::text(w[0]), Block::text(w[1]),
                       Block::text(w[2]), Block::text(second[0]), Block::text(second[1]), Block::text(second[2])));
    kinds.push_back(kind);
  }
  return kinds;
}

/// `inline void support_jacobian_<link>(q, point, J) noexcept` and a line break (two when long).
std::string supportSignature(const BodyFrame & bf)
{
  const std::string head = fmt::format("inline void support_jacobian_{}(const Config<S> & q, const Vec3<S> & point,", bf.ident);
  const std::string tail = "LinkJacobian<S> & J) noexcept\n";
  return head.size() + tail.size() < 120 ? head + " " + tail : head + "\n    " + tail;
}

} // namespace

void writePointColumns(Block & b, const MovingJoint & mj, const JointKernel & K, const Xform & X0, const Vec3 & p)
{
  // [R s_w; R s_v + (R s_w) x (p - o_k)],  R = E_0_k^T, o_k = origin of joint k's frame
  const std::string h = fmt::format("J_{}", mj.tag);
  const Vec3 po = sub(b, p, X0.r, h + "_po");
  for(int d = 0; d < mj.nv; ++d)
  {
    const Motion & Sd = K.S[static_cast<std::size_t>(d)];
    const Vec3 w = tmul(b, X0.E, Sd.w, fmt::format("{}_w{}", h, d));
    const Vec3 v = add(b, tmul(b, X0.E, Sd.v, fmt::format("{}_Rv{}", h, d)), cross(b, w, po, fmt::format("{}_wxp{}", h, d)),
                       fmt::format("{}_v{}", h, d));
    writeColumn(b, "J", mj.vIndex + d, w, v);
  }
}

EmittedBody jacobianBody(const RobotModel & rm)
{
  // Column of dof d of joint k (world axes, at the link origin p):
  //   [R s_w; R s_v + (R s_w) x (p - o_k)],  R = E_0_k^T, o_k = origin of joint k's frame;
  // a rotation (s_v = 0) by detail::put_rotation(J, c, R s_w, p - o_k).
  Block b;
  b.line("const Eigen::Matrix<S, 3, 1> p = kin.pose[detail::at(body)].translation;");
  const Vec3 p = vec3Var("p");
  emitJumpWalk(b, rm, "jac", "its columns", [&](Block & jb, int k, const MovingJoint & mj) {
    // S depends on q only for backward multi-dof joints
    const JointKernel K = emitJointKernel(jb, mj, "kin.q");
    const Xform X0 = kinFrame(k);
    bool rotations = true;
    for(const Motion & Sd : K.S) rotations = rotations && isZero(Sd.v);
    if(!rotations)
    {
      writePointColumns(jb, mj, K, X0, p);
      return;
    }
    for(int d = 0; d < mj.nv; ++d)
    {
      const Vec3 w = tmul(jb, X0.E, K.S[static_cast<std::size_t>(d)].w, fmt::format("J_{}_w{}", mj.tag, d));
      jb.line(fmt::format("detail::put_rotation<S>(J, {}, {}, {}, {}, p - kin.frame[{}].translation);", mj.vIndex + d,
                         Block::text(w[0]), Block::text(w[1]), Block::text(w[2]), k));
    }
  });
  return finish(b);
}

std::string supportJacobianDefinitions(const RobotModel & rm)
{
  std::string out = "/// A link's Jacobian: 6 x nv, rows [angular; linear] in world axes.\n"
                    "template<class S>\n"
                    "using LinkJacobian = Eigen::Matrix<S, 6, nv>;\n\n"
                    "/// J(:, c) = [w; w x d]: the column of a rotation about the axis w (world) through the point at\n"
                    "/// -d from the Jacobian's point.\n"
                    "template<class S>\n"
                    "RBDGEN_INLINE void put_rotation(LinkJacobian<S> & J, int c, const S & wx, const S & wy, const S & wz, const Vec3<S> & d) noexcept\n"
                    "{\n"
                    "  // every value read before the first store: J may alias what wx, wy, wz refer to (kin's poses)\n"
                    "  const S x = wx, y = wy, z = wz, nx = wy * d(2) - wz * d(1), ny = wz * d(0) - wx * d(2), nz = wx * d(1) - wy * d(0);\n"
                    "  J(0, c) = x;\n"
                    "  J(1, c) = y;\n"
                    "  J(2, c) = z;\n"
                    "  J(3, c) = nx;\n"
                    "  J(4, c) = ny;\n"
                    "  J(5, c) = nz;\n"
                    "}\n\n"
                    "/// J(:, c) from the column m of a support step and the point p (world): kind 0, a translation\n"
                    "/// m = [0; u]: [0; u]; kind 1, a rotation about an axis through o, m = [w; o]: [w; w x (p - o)];\n"
                    "/// kind 2, m = [w; v] the column at the world origin: [w; v + w x p].\n"
                    "template<class S, int kind>\n"
                    "RBDGEN_INLINE void put_column(LinkJacobian<S> & J, int c, const Motion<S> & m, const Vec3<S> & p) noexcept\n"
                    "{\n"
                    "  if constexpr(kind == 1) put_rotation<S>(J, c, m(0), m(1), m(2), Vec3<S>(p(0) - m(3), p(1) - m(4), p(2) - m(5)));\n"
                    "  else\n"
                    "  {\n"
                    "    J(0, c) = m(0);\n"
                    "    J(1, c) = m(1);\n"
                    "    J(2, c) = m(2);\n"
                    "    J(3, c) = kind == 0 ? m(3) : m(3) + (m(1) * p(2) - m(2) * p(1));\n"
                    "    J(4, c) = kind == 0 ? m(4) : m(4) + (m(2) * p(0) - m(0) * p(2));\n"
                    "    J(5, c) = kind == 0 ? m(5) : m(5) + (m(0) * p(1) - m(1) * p(0));\n"
                    "  }\n"
                    "}\n\n"
                    "/// Columns [c0, c0 + n) of J set to zero (one function for every range: a block expression per\n"
                    "/// size was a template instance each).\n"
                    "template<class S>\n"
                    "RBDGEN_INLINE void zero_columns(LinkJacobian<S> & J, int c0, int n) noexcept\n"
                    "{\n"
                    "  for(int c = c0; c < c0 + n; ++c)\n"
                    "    for(int r = 0; r < 6; ++r) J(r, c) = S(0);\n"
                    "}\n\n"
                    "/// o + E^T x: the world coordinates of the point x of a frame whose world pose is X = (E, o).\n"
                    "template<class S>\n"
                    "RBDGEN_INLINE Vec3<S> world_point(const Pose<S> & X, const Vec3<S> & x) noexcept\n"
                    "{\n"
                    "  const Mat3<S> & E = X.rotation;\n"
                    "  const Vec3<S> & o = X.translation;\n"
                    "  return Vec3<S>(o(0) + (E(0, 0) * x(0) + E(1, 0) * x(1) + E(2, 0) * x(2)),\n"
                    "                 o(1) + (E(0, 1) * x(0) + E(1, 1) * x(1) + E(2, 1) * x(2)),\n"
                    "                 o(2) + (E(0, 2) * x(0) + E(1, 2) * x(1) + E(2, 2) * x(2)));\n"
                    "}\n\n"
                    "// One step of the walk from q along a support path per moving joint: the walk's pose X from the\n"
                    "// world pose of the joint's parent body to its own; the joint's columns in col0, col1... (every\n"
                    "// entry; stored as put_column reads them).\n";
  // how each velocity coordinate's column is stored; the columns are separate 6-vectors written
  // whole by the steps, so that the compilers keep them in registers (a 6 x 6 block for a free
  // joint, zero-initialised, stayed in memory)
  std::vector<std::vector<ColumnKind>> kinds(rm.joints.size());
  auto colParams = [](const MovingJoint & mj) {
    std::string params;
    for(int d = 0; d < mj.nv; ++d) params += fmt::format(", Motion<S> & col{}", d);
    return params;
  };
  out += supportStepFunctions(rm, "support_step", colParams, [&](Block & b, int k, const JointKernel & K, const Xform & X0) {
    kinds[static_cast<std::size_t>(k)] = writeSupportColumns(b, K, X0);
  });
  // one function per joint's own link (X_owner_link = identity): its walk keeping each joint's
  // columns, its pose, the columns at the point; a link fixed to it at an offset calls it with the
  // point in the owner's coordinates (so the code grows with the joints' path lengths, not the links')
  std::vector<int> frameLink(rm.joints.size(), -1);
  for(std::size_t i = 0; i < rm.bodies.size(); ++i)
  {
    const BodyFrame & bf = rm.bodies[i];
    if(bf.owner >= 0 && bf.atOwnerFrame() && frameLink[static_cast<std::size_t>(bf.owner)] < 0) frameLink[static_cast<std::size_t>(bf.owner)] = static_cast<int>(i);
  }
  std::string cases, staticCases, fixedLinks; // (the fixed links' functions after all their owners')
  for(std::size_t i = 0; i < rm.bodies.size(); ++i)
  {
    const BodyFrame & bf = rm.bodies[i];
    if(bf.owner < 0) // on the world: no column
    {
      staticCases += fmt::format("{}case Body::{}:", staticCases.empty() ? "  " : " ", bf.ident);
      continue;
    }
    cases += fmt::format("  case Body::{0}: support_jacobian_{0}<S>(q, point, J); return;\n", bf.ident);
    const int frame = frameLink[static_cast<std::size_t>(bf.owner)];
    if(frame >= 0 && frame != static_cast<int>(i))
    {
      // X_c = (E_c, r_c) the link in its owner's frame: the point in the owner's coordinates, r_c + E_c^T point
      const BodyFrame & owner = rm.bodies[static_cast<std::size_t>(frame)];
      Block b;
      const Xform C = linkXform(bf);
      const Vec3 po = add(b, C.r, tmul(b, C.E, vec3Var("point"), "po_Et"), "po");
      b.line(fmt::format("const Vec3<S> point_owner({}, {}, {});", Block::text(po[0]), Block::text(po[1]), Block::text(po[2])));
      b.line(fmt::format("support_jacobian_{}<S>(q, point_owner, J);", owner.ident));
      fixedLinks += fmt::format("/// link '{}': fixed to '{}'\n"
                                "template<class S>\n"
                                "{}"
                                "{{\n{}}}\n\n",
                                bf.name, owner.name, supportSignature(bf), b.str("  "));
      continue;
    }
    Block b;
    const std::vector<int> path = rm.path(bf.owner);
    std::string names, line = "Motion<S>";
    for(int k : path)
    {
      const MovingJoint & mj = rm.joints[static_cast<std::size_t>(k)];
      for(int d = 0; d < mj.nv; ++d)
      {
        const std::string item = fmt::format(" col_{}_{},", mj.tag, d);
        if(line.size() + item.size() > 110)
        {
          names += line + "\n  ";
          line = "   ";
        }
        line += item;
      }
    }
    line.back() = ';';
    b.line(names + line);
    const Xform X = emitLinkWalk(b, rm, bf, "support_step", [](const MovingJoint & mj) {
      std::string args;
      for(int d = 0; d < mj.nv; ++d) args += fmt::format(", col_{}_{}", mj.tag, d);
      return args;
    });
    // p = o_link + E_link^T point (the link's frame is its owner's, at the walk's end: world_point)
    if(frame == static_cast<int>(i)) b.line("const Vec3<S> p = detail::world_point(walk, point);");
    else
    {
      const Vec3 p = add(b, X.r, tmul(b, X.E, vec3Var("point"), "p_Et"), "p");
      b.line(fmt::format("const Vec3<S> p({}, {}, {});", Block::text(p[0]), Block::text(p[1]), Block::text(p[2])));
    }
    for(int k : path)
    {
      const MovingJoint & mj = rm.joints[static_cast<std::size_t>(k)];
      for(int d = 0; d < mj.nv; ++d)
        b.line(fmt::format("detail::put_column<S, {}>(J, {}, col_{}_{}, p);",
                           static_cast<int>(kinds[static_cast<std::size_t>(k)][static_cast<std::size_t>(d)]), mj.vIndex + d, mj.tag, d));
    }
    // the other columns: zero
    std::vector<bool> onPath(static_cast<std::size_t>(rm.nv), false);
    for(int k : path)
    {
      const MovingJoint & mj = rm.joints[static_cast<std::size_t>(k)];
      for(int d = 0; d < mj.nv; ++d) onPath[static_cast<std::size_t>(mj.vIndex + d)] = true;
    }
    for(int c = 0; c < rm.nv;)
    {
      if(onPath[static_cast<std::size_t>(c)])
      {
        ++c;
        continue;
      }
      int n = 1;
      while(c + n < rm.nv && !onPath[static_cast<std::size_t>(c + n)]) ++n;
      b.line(fmt::format("detail::zero_columns<S>(J, {}, {});", c, n));
      c += n;
    }
    std::string joints;
    for(int k : path) joints += " '" + rm.joints[static_cast<std::size_t>(k)].name + "'";
    out += fmt::format("/// link '{}': support path{}\n"
                       "template<class S>\n"
                       "{}"
                       "{{\n{}}}\n\n",
                       bf.name, joints, supportSignature(bf), b.str("  "));
  }
  out += fixedLinks;
  out += "/// From q, along `body`'s support path only: J (world axes, at `point`, given in link coordinates;\n"
         "/// the columns of the joints off the path are zero). Shared by jacobian() and\n"
         "/// jacobian_dot_times_alpha() from q.\n"
         "template<class S>\n"
         "inline void support_jacobian(Body body, const Config<S> & q, const Vec3<S> & point, LinkJacobian<S> & J) noexcept\n"
         "{\n"
         "  switch(body)\n"
         "  {\n" +
         cases + (staticCases.empty() ? "" : staticCases + " break; // on the world: no column\n") +
         "  }\n"
         "  J.setZero(); // (a link on the world, or not a Body)\n"
         "}";
  return out;
}

EmittedBody comJacobianBody(const RobotModel & rm)
{
  Block b;
  PassContext ctx(b, rm, "kin.q");
  const std::size_t n = rm.joints.size();
  // Subtree mass and first moment (world): M_j, h_j = sum over the subtree of m_k o_k + E_0_k^T h_k.
  std::vector<double> mass(n, 0.0);
  std::vector<Vec3> moment(n, Vec3::zero());
  for(std::size_t k = n; k-- > 0;)
  {
    const MovingJoint & mj = rm.joints[k];
    if(mj.inertia.mass() != 0.0) moment[k] = add(b, moment[k], firstMoment(ctx, static_cast<int>(k), kinFrame(static_cast<int>(k))), mj.tag + "_hs");
    mass[k] += mj.inertia.mass();
    if(mj.parent >= 0)
    {
      const auto p = static_cast<std::size_t>(mj.parent);
      mass[p] += mass[k];
      moment[p] = add(b, moment[p], moment[k], rm.joints[p].tag + "_hs");
    }
  }
  // Column of dof d of joint j: (w x (h_j - M_j o_j) + M_j R s_v) / M, with w = R s_w; a rotation
  // (s_v = 0) by detail::put_com_rotation.
  const double invM = rm.totalMass > 0 ? 1.0 / rm.totalMass : 0.0;
  for(std::size_t k = 0; k < n; ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    const JointKernel & K = ctx.kernel(static_cast<int>(k));
    const Xform X0 = kinFrame(static_cast<int>(k));
    const Vec3 rel = sub(b, moment[k], scale(b, Scalar::constant(mass[k]), X0.r, mj.tag + "_Mo"), mj.tag + "_rel");
    for(int d = 0; d < mj.nv; ++d)
    {
      const Motion & Sd = K.S[static_cast<std::size_t>(d)];
      const std::string h = fmt::format("{}_c{}", mj.tag, d);
      const Vec3 w = tmul(b, X0.E, Sd.w, h + "_w");
      if(isZero(Sd.v) && invM != 0.0)
      {
        b.line(fmt::format("detail::put_com_rotation<S>(J, {}, {}, {}, {}, {}, {}, {}, {});", mj.vIndex + d, Block::text(w[0]),
                           Block::text(w[1]), Block::text(w[2]), Block::text(rel[0]), Block::text(rel[1]), Block::text(rel[2]),
                           Block::literal(invM)));
        continue;
      }
      const Vec3 col = add(b, cross(b, w, rel, h + "_wxh"), scale(b, Scalar::constant(mass[k]), tmul(b, X0.E, Sd.v, h + "_Rv"), h + "_Mv"), h);
      for(int r = 0; r < 3; ++r)
      {
        const Scalar x = b.sum({Term{invM, {col[r]}}}, fmt::format("{}_{}", h, r));
        if(!x.isZero()) b.line(fmt::format("J({}, {}) = {};", r, mj.vIndex + d, Block::text(x)));
      }
    }
  }
  return finish(b);
}

} // namespace rbdgen::emit
