#include "SupportPath.h"

#include <algorithm>
#include <cctype>
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

/// A step reads q beyond its angle's sin and cos (all but revolute joints).
bool readsConfig(const MovingJoint & mj)
{
  return mj.joint.type() != rbd::Joint::Rev;
}

/// The emitted text reads or writes the local `name` (not as part of a longer name).
bool mentions(const std::string & text, const std::string & name)
{
  for(auto p = text.find(name); p != std::string::npos; p = text.find(name, p + 1))
  {
    const auto part = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    if((p == 0 || !part(text[p - 1])) && (p + name.size() >= text.size() || !part(text[p + name.size()]))) return true;
  }
  return false;
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
// copied first (the assignments run in order); entries already in place are skipped, and so are the
// constants of the identity when E, o hold it (a walk's first step).
void assignPose(Block & b, const std::string & E, const std::string & o, const Xform & X, bool fromIdentity)
{
  std::vector<std::pair<std::string, Scalar>> moves;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) moves.emplace_back(fmt::format("{}({}, {})", E, r, c), X.E(r, c));
  for(int i = 0; i < 3; ++i) moves.emplace_back(fmt::format("{}({})", o, i), X.r[i]);
  auto readsTarget = [&](const Scalar & x) {
    return !x.isConst() && (x.name().rfind(E + "(", 0) == 0 || x.name().rfind(o + "(", 0) == 0);
  };
  for(auto & [dst, x] : moves)
    if(readsTarget(x) && x.name() != dst) x = b.def(x.name(), "walk_copy");
  for(std::size_t m = 0; m < moves.size(); ++m)
  {
    const auto & [dst, x] = moves[m];
    const double identity = m < 9 && m % 4 == 0 ? 1.0 : 0.0; // (E(r, r) are entries 0, 4 and 8)
    if(x.isConst() && fromIdentity && x.value() == identity) continue;
    if(x.isConst() || x.name() != dst) b.line(fmt::format("{} = {};", dst, Block::text(x)));
  }
}

} // namespace

std::string supportPathTables(const RobotModel & rm)
{
  const std::size_t D = maxDepth(rm);
  std::string depth, paths;
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
    begin += fmt::format("{}{}", begin.empty() ? "" : ", ", mj.vIndex);
    count += fmt::format("{}{}", count.empty() ? "" : ", ", mj.nv);
  }
  if(!paths.empty()) paths.pop_back();
  const std::size_t slots = std::max<std::size_t>(rm.joints.size(), 1);
  return fmt::format("/// Support paths (moving joints from the root to each link's owner, root first) for the functions\n"
                     "/// that loop over the path of a Body given at run time.\n"
                     "constexpr int max_support_depth = {};\n"
                     "constexpr std::array<int, nbodies> support_depth = {{ {} }};\n"
                     "constexpr std::array<std::array<int, max_support_depth>, nbodies> support_path = {{{{\n{}\n}}}};\n"
                     "/// First velocity coordinate and number of velocity coordinates of each moving joint.\n"
                     "constexpr std::array<int, {}> dof_begin = {{ {} }};\n"
                     "constexpr std::array<int, {}> dof_count = {{ {} }};",
                     D, depth, paths, slots, begin.empty() ? "0" : begin, slots,
                     count.empty() ? "0" : count);
}

void emitJumpWalk(Block & b, const RobotModel & rm, const std::string & prefix, const std::string & what,
                  const std::function<void(Block & jb, int k, const MovingJoint & mj)> & jointBlock)
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
  bool doneUsed = std::find(owners.begin(), owners.end(), -1) != owners.end(); // (a link on the world)
  for(std::size_t k = rm.joints.size(); k-- > 0;)
  {
    // a joint's statements between braces when they declare locals (a jump may not cross them), and
    // a jump to its parent unless the parent's block comes next
    Block jb;
    jointBlock(jb, static_cast<int>(k), rm.joints[k]);
    std::vector<std::string> lines; // (its statements after the removal of unused locals)
    const std::string text = jb.str("");
    for(std::size_t from = 0, to; (to = text.find('\n', from)) != std::string::npos; from = to + 1) lines.push_back(text.substr(from, to - from));
    bool declares = false;
    for(const std::string & l : lines) declares = declares || l.rfind("const ", 0) == 0 || l.rfind("[[maybe_unused]] const ", 0) == 0;
    b.line(fmt::format("{}:{} // joint '{}': {}", label(static_cast<int>(k)), declares ? " {" : "", rm.joints[k].name, what));
    for(const std::string & l : lines) b.line(l);
    const int parent = rm.joints[k].parent;
    const std::string jump = parent == static_cast<int>(k) - 1 ? "" : fmt::format("goto {};", label(parent));
    doneUsed = doneUsed || (parent < 0 && !jump.empty());
    if(declares) b.line(jump.empty() ? "}" : "} " + jump);
    else if(!jump.empty()) b.line(jump);
  }
  if(doneUsed) b.line(label(-1) + ":;"); // (else every path falls through to here: an unused label is a warning)
}

std::string supportStepFunctions(const RobotModel & rm, const std::string & prefix,
                                 const std::function<std::string(const MovingJoint &)> & extraParams,
                                 const std::function<void(Block & b, int k, const JointKernel & K, const Xform & X0)> & jointBlock)
{
  std::string out;
  const Xform walk = poseVars("X.rotation", "X.translation"); // (the walk's pose)
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
  {
    const MovingJoint & mj = rm.joints[k];
    Block b;
    const AngleSinCos angles = [](int) { return std::make_pair(Scalar::var("s"), Scalar::var("c")); };
    const JointKernel K = emitJointKernel(b, mj, "q", angles);
    const Xform Xt = treeXform(mj);
    // X_0_k = X_j X_T X_0_p (X_0_p = identity for a joint on the world)
    const Xform X0 = compose(b, K.Xj, mj.parent < 0 ? Xt : compose(b, Xt, walk, mj.tag + "_X0t"), mj.tag + "_X0");
    jointBlock(b, static_cast<int>(k), K, X0);
    assignPose(b, "X.rotation", "X.translation", X0, mj.parent < 0); // (a joint on the world starts every walk: identity)
    const std::string body = b.str("  ");
    auto param = [&](const std::string & type, const std::string & name) {
      return (mentions(body, name) ? "" : "[[maybe_unused]] ") + type + " " + name;
    };
    std::string params = (readsConfig(mj) ? "const Config<S> & q, " : "") + std::string(hasAngle(mj) ? "const S & s, const S & c, " : "") +
                         param("Pose<S> &", "X") + extraParams(mj);
    const std::string head = fmt::format("RBDGEN_INLINE void {}_{}(", prefix, mj.tag);
    if(head.size() + params.size() + 11 > 120) params = "\n    " + params; // (11: ") noexcept")
    out += fmt::format("/// joint '{}' ({}){}\n"
                       "template<class S>\n"
                       "{}{}) noexcept\n"
                       "{{\n{}}}\n\n",
                       mj.name, describeJoint(mj), mj.parent < 0 ? ", on the world" : "", head, params, body);
  }
  return out;
}

Xform emitLinkWalk(Block & b, const RobotModel & rm, const BodyFrame & bf, const std::string & prefix,
                   const std::function<std::string(const MovingJoint &)> & extraArgs)
{
  const std::vector<int> path = bf.owner < 0 ? std::vector<int>{} : rm.path(bf.owner);
  if(path.empty()) return linkXform(bf);
  // the path's angles, by runs of consecutive q indices: one vectorised sin/cos per run, read in place
  std::vector<int> angleJoints;
  for(int k : path)
    if(hasAngle(rm.joints[static_cast<std::size_t>(k)])) angleJoints.push_back(k);
  std::vector<std::string> sinCos(rm.joints.size());
  for(std::size_t i = 0, run = 0; i < angleJoints.size(); ++run)
  {
    std::size_t n = 1;
    const int first = rm.joints[static_cast<std::size_t>(angleJoints[i])].qIndex;
    while(i + n < angleJoints.size() && rm.joints[static_cast<std::size_t>(angleJoints[i + n])].qIndex == first + static_cast<int>(n)) ++n;
    const std::string name = fmt::format("sc{}", run);
    b.line(fmt::format("const auto {} = detail::sincos_span<S, {}>(q.data() + {});", name, n, first));
    for(std::size_t j = 0; j < n; ++j) sinCos[static_cast<std::size_t>(angleJoints[i + j])] = fmt::format("{0}.s[{1}], {0}.c[{1}], ", name, j);
    i += n;
  }
  b.line("Pose<S> walk{detail::Mat3<S>::Identity(), detail::Vec3<S>::Zero()};");
  for(int k : path)
  {
    const MovingJoint & mj = rm.joints[static_cast<std::size_t>(k)];
    b.line(fmt::format("detail::{}_{}<S>({}{}walk{});", prefix, mj.tag, readsConfig(mj) ? "q, " : "",
                       sinCos[static_cast<std::size_t>(k)], extraArgs(mj)));
  }
  // X_0_link = X_owner_link X_0_owner (the owner's pose is the walk's end)
  return compose(b, linkXform(bf), poseVars("walk.rotation", "walk.translation"), "L_" + bf.ident);
}

} // namespace rbdgen::passes
