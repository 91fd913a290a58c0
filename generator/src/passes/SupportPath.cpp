#include "SupportPath.h"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

namespace rbdgen::passes
{
namespace
{

bool hasAngle(const MovingJoint & mj)
{
  const auto t = mj.joint.type();
  return t == rbd::Joint::Rev || t == rbd::Joint::Cylindrical || t == rbd::Joint::Planar;
}

std::size_t maxDepth(const RobotModel & rm)
{
  std::size_t d = 1; // arrays of size 0 are not C++
  for(const BodyFrame & bf : rm.bodies)
    if(bf.owner >= 0) d = std::max(d, rm.path(bf.owner).size());
  return d;
}

Xform poseVars(const std::string & E, const std::string & o)
{
  Xform X;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) X.E(r, c) = Scalar::var(fmt::format("{}({}, {})", E, r, c));
  for(int i = 0; i < 3; ++i) X.r[i] = Scalar::var(fmt::format("{}({})", o, i));
  return X;
}

// E = X.E, o = X.r for mutable E, o that X may read: entries that are other entries of E or o are
// copied first (the assignments run in order), entries already in place are skipped.
// E, o = X entry by entry; an entry already equal to its value is skipped (E and o hold the pose
// named fromE, fromO: E itself, or the pose they were initialised from).
void assignPose(Block & b, const std::string & E, const std::string & o, const Xform & X, std::string fromE = "",
                std::string fromO = "")
{
  if(fromE.empty()) fromE = E;
  if(fromO.empty()) fromO = o;
  std::vector<std::pair<std::string, Scalar>> moves;
  std::vector<std::string> current;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c)
    {
      moves.emplace_back(fmt::format("{}({}, {})", E, r, c), X.E(r, c));
      current.push_back(fmt::format("{}({}, {})", fromE, r, c));
    }
  for(int i = 0; i < 3; ++i)
  {
    moves.emplace_back(fmt::format("{}({})", o, i), X.r[i]);
    current.push_back(fmt::format("{}({})", fromO, i));
  }
  auto readsTarget = [&](const Scalar & x) {
    return !x.isConst() && (x.name().rfind(E + "(", 0) == 0 || x.name().rfind(o + "(", 0) == 0);
  };
  for(auto & [dst, x] : moves)
    if(readsTarget(x) && x.name() != dst) x = b.def(x.name(), "walk_copy");
  for(std::size_t m = 0; m < moves.size(); ++m)
  {
    const auto & [dst, x] = moves[m];
    if(x.isConst() || (x.name() != dst && x.name() != current[m])) b.line(fmt::format("{} = {};", dst, Block::text(x)));
  }
}

} // namespace

std::string supportPathTables(const RobotModel & rm)
{
  const std::size_t D = maxDepth(rm);
  std::string depth, paths, angles;
  for(const BodyFrame & bf : rm.bodies)
  {
    const std::vector<int> path = bf.owner < 0 ? std::vector<int>{} : rm.path(bf.owner);
    depth += fmt::format("{}{}", depth.empty() ? "" : ", ", path.size());
    std::string row;
    for(std::size_t i = 0; i < D; ++i) row += fmt::format("{}{}", i ? ", " : "", i < path.size() ? path[i] : 0);
    paths += fmt::format("    {{{{{}}}}}, // {}\n", row, bf.name);
  }
  std::string begin, count;
  for(const MovingJoint & mj : rm.joints)
  {
    angles += fmt::format("{}{}", angles.empty() ? "" : ", ", hasAngle(mj) ? mj.qIndex : 0);
    begin += fmt::format("{}{}", begin.empty() ? "" : ", ", mj.vIndex);
    count += fmt::format("{}{}", count.empty() ? "" : ", ", mj.nv);
  }
  if(!paths.empty()) paths.pop_back();
  const std::size_t slots = std::max<std::size_t>(rm.joints.size(), 1);
  return fmt::format("/// Support paths (moving joints from the root to each link's owner, root first) for the functions\n"
                     "/// that take a Body and q; angle_index: the q index of each moving joint's angle (0: none).\n"
                     "constexpr int max_support_depth = {};\n"
                     "constexpr std::array<int, nbodies> support_depth = {{ {} }};\n"
                     "constexpr std::array<std::array<int, max_support_depth>, nbodies> support_path = {{{{\n{}\n}}}};\n"
                     "constexpr std::array<int, {}> angle_index = {{ {} }};\n"
                     "/// First velocity coordinate and number of velocity coordinates of each moving joint.\n"
                     "constexpr std::array<int, {}> dof_begin = {{ {} }};\n"
                     "constexpr std::array<int, {}> dof_count = {{ {} }};",
                     D, depth, paths, slots, angles.empty() ? "0" : angles, slots, begin.empty() ? "0" : begin, slots,
                     count.empty() ? "0" : count);
}

void emitJumpWalk(Block & b, const RobotModel & rm, const std::string & prefix, const std::string & what,
                  const std::function<void(int k, const MovingJoint & mj)> & jointBlock)
{
  auto label = [&](int k) {
    return k < 0 ? prefix + "_done" : fmt::format("{}_{}", prefix, rm.joints[static_cast<std::size_t>(k)].tag);
  };
  b.line("switch(body)");
  b.line("{");
  // the links owned by one joint share a line: case Body::a: case Body::b: goto <owner>;
  std::vector<int> owners;
  for(const BodyFrame & bf : rm.bodies)
    if(std::find(owners.begin(), owners.end(), bf.owner) == owners.end()) owners.push_back(bf.owner);
  for(int owner : owners)
  {
    std::string text, line;
    for(const BodyFrame & bf : rm.bodies)
    {
      if(bf.owner != owner) continue;
      const std::string item = fmt::format("case Body::{}:", bf.ident);
      if(!line.empty() && line.size() + item.size() > 100)
      {
        text += line + "\n  ";
        line.clear();
      }
      line += (line.empty() ? "" : " ") + item;
    }
    b.line(text + line + fmt::format(" goto {};", label(owner)));
  }
  b.line("}");
  for(std::size_t k = rm.joints.size(); k-- > 0;)
  {
    b.line(fmt::format("{}: {{ // joint '{}': {}", label(static_cast<int>(k)), rm.joints[k].name, what));
    jointBlock(static_cast<int>(k), rm.joints[k]);
    b.line(fmt::format("}} goto {};", label(rm.joints[k].parent)));
  }
  b.line(label(-1) + ":;");
}

Xform emitPathLoop(Block & b, const RobotModel & rm, const std::string & q,
                   const std::function<void(int k, const JointKernel & K, const Xform & X0)> & jointBlock)
{
  b.comment("the support path of `body`, root first; sin/cos of its angles in one batch");
  b.line("const int walk_depth = detail::support_depth[static_cast<std::size_t>(body)];");
  b.line("const auto & walk_path = detail::support_path[static_cast<std::size_t>(body)];");
  b.line("S walk_angles[detail::max_support_depth] = {};");
  b.line("for(int i = 0; i < walk_depth; ++i)");
  b.line(fmt::format("  walk_angles[i] = {}[detail::angle_index[static_cast<std::size_t>(walk_path[static_cast<std::size_t>(i)])]];", q));
  b.line("[[maybe_unused]] const auto walk_sc = detail::sincos_all(walk_angles); // (no angle on any path: unused)");
  b.comment("world pose of the body reached so far: walk_E (world to body), walk_o (origin, world)");
  b.line("Eigen::Matrix<S, 3, 3> walk_E = Eigen::Matrix<S, 3, 3>::Identity();");
  b.line("Eigen::Matrix<S, 3, 1> walk_o = Eigen::Matrix<S, 3, 1>::Zero();");
  b.line("for(int walk_i = 0; walk_i < walk_depth; ++walk_i)");
  b.line("{");
  b.line("switch(walk_path[static_cast<std::size_t>(walk_i)])");
  b.line("{");
  const AngleSinCos angles = [](int) {
    return std::make_pair(Scalar::var("walk_sc.s[walk_i]"), Scalar::var("walk_sc.c[walk_i]"));
  };
  const Xform walk = poseVars("walk_E", "walk_o");
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    b.line(fmt::format("case {}: {{ // joint '{}' ({})", k, mj.name, describeJoint(mj)));
    const JointKernel K = emitJointKernel(b, mj, q, angles);
    const Xform Xt = treeXform(mj);
    // X_0_k = X_j X_T X_0_p, X_0_p = identity for a joint on the world
    const Xform X0 = compose(b, K.Xj, mj.parent < 0 ? Xt : compose(b, Xt, walk, mj.tag + "_X0t"), mj.tag + "_X0");
    jointBlock(static_cast<int>(k), K, X0);
    assignPose(b, "walk_E", "walk_o", X0);
    b.line("} break;");
  }
  b.line("default: break;");
  b.line("}");
  b.line("}");
  return walk;
}

void emitLinkPoseFromWalk(Block & b, const RobotModel & rm, bool rotation)
{
  b.comment("the link's world pose from its owner's: E_link = E_c walk_E, o_link = walk_o + walk_E^T r_c");
  if(rotation) b.line("Eigen::Matrix<S, 3, 3> link_E = walk_E;");
  b.line("Eigen::Matrix<S, 3, 1> link_o = walk_o;");
  b.line("switch(body)");
  b.line("{");
  const Xform walk = poseVars("walk_E", "walk_o");
  for(const BodyFrame & bf : rm.bodies)
  {
    const sva::PTransformd & C = bf.X_owner_link;
    if(C.translation().isZero(0.0) && (!rotation || C.rotation().isIdentity(0.0))) continue;
    b.line(fmt::format("case Body::{}: {{", bf.ident));
    const Xform X = compose(b, linkXform(bf), walk, "L_" + bf.ident);
    if(rotation) assignPose(b, "link_E", "link_o", X, "walk_E", "walk_o");
    else
      for(int i = 0; i < 3; ++i) b.line(fmt::format("link_o({}) = {};", i, Block::text(X.r[i])));
    b.line("} break;");
  }
  b.line("default: break;");
  b.line("}");
}

} // namespace rbdgen::passes
