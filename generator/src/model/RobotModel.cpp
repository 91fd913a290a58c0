#include "RobotModel.h"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <set>
#include <stdexcept>

namespace rbdgen
{

std::string sanitizeIdentifier(const std::string & name)
{
  std::string out;
  for(char c : name)
  {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) != 0;
    const char x = ok ? c : '_';
    if(x == '_' && !out.empty() && out.back() == '_') continue; // no "__" (reserved)
    out += x;
  }
  if(out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "_" + out;
  if(out[0] == '_' && out.size() > 1 && std::isupper(static_cast<unsigned char>(out[1]))) out = "x" + out; // _X reserved
  while(out.size() > 1 && out.back() == '_') out.pop_back();
  static const std::set<std::string> keywords{
      "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch", "char",
      "char16_t", "char32_t", "char8_t", "class", "compl", "concept", "const", "consteval", "constexpr", "constinit",
      "const_cast", "continue", "co_await", "co_return", "co_yield", "decltype", "default", "delete", "do", "double",
      "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for", "friend", "goto", "if",
      "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq", "nullptr", "operator", "or",
      "or_eq", "private", "protected", "public", "register", "reinterpret_cast", "requires", "return", "short",
      "signed", "sizeof", "static", "static_assert", "static_cast", "struct", "switch", "template", "this",
      "thread_local", "throw", "true", "try", "typedef", "typeid", "typename", "union", "unsigned", "using",
      "virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq"};
  if(keywords.count(out)) out += "_";
  return out;
}

sva::PTransformd snapTransform(const sva::PTransformd & X, double tol)
{
  auto snap = [tol](double x) {
    for(double target : {-1.0, 0.0, 1.0})
      if(std::abs(x - target) <= tol) return target;
    return x;
  };
  Eigen::Matrix3d E = X.rotation();
  Eigen::Vector3d r = X.translation();
  for(int i = 0; i < 9; ++i) E(i) = snap(E(i));
  for(int i = 0; i < 3; ++i) r(i) = std::abs(r(i)) <= tol ? 0.0 : r(i);
  return sva::PTransformd(E, r);
}

std::vector<int> RobotModel::path(int k) const
{
  std::vector<int> p;
  for(int j = k; j >= 0; j = joints[static_cast<std::size_t>(j)].parent) p.push_back(j);
  std::reverse(p.begin(), p.end());
  return p;
}

RobotModel buildRobotModel(const rbd::MultiBody & mb, const std::vector<sva::PTransformd> & X_mb_link,
                           const std::string & robotName)
{
  RobotModel rm;
  rm.name = robotName;
  rm.nq = mb.nrParams();
  rm.nv = mb.nrDof();
  const auto n = static_cast<std::size_t>(mb.nrBodies());
  if(X_mb_link.size() != n) throw std::invalid_argument("buildRobotModel: one link transform per body expected");

  // owner[i]: moving joint carrying body i; X_owner_mb[i]: from the owner's body frame (world when
  // static) to body i's MultiBody frame.
  std::vector<int> owner(n, -1);
  std::vector<sva::PTransformd> X_owner_mb(n, sva::PTransformd::Identity());
  std::vector<int> movingOfBody(n, -1);
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & j = mb.joint(i);
    const int p = mb.parent(i);
    const int parentOwner = p < 0 ? -1 : owner[static_cast<std::size_t>(p)];
    const sva::PTransformd X_owner_p = p < 0 ? sva::PTransformd::Identity() : X_owner_mb[static_cast<std::size_t>(p)];
    if(j.type() == rbd::Joint::Fixed)
    {
      owner[k] = parentOwner;
      // X_owner_i = X_T,i X_owner_p (fixed joint: X_j = identity)
      X_owner_mb[k] = mb.transform(i) * X_owner_p;
      continue;
    }
    MovingJoint mj;
    mj.name = j.name();
    mj.joint = j;
    mj.mbIndex = i;
    mj.parent = parentOwner;
    mj.Xt = snapTransform(mb.transform(i) * X_owner_p);
    mj.qIndex = mb.jointPosInParam(i);
    mj.vIndex = mb.jointPosInDof(i);
    mj.nq = j.params();
    mj.nv = j.dof();
    mj.inertia = sva::RBInertiad(0.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
    mj.tag = "j" + std::to_string(rm.joints.size());
    movingOfBody[k] = static_cast<int>(rm.joints.size());
    owner[k] = movingOfBody[k];
    X_owner_mb[k] = sva::PTransformd::Identity();
    for(int d = 0; d < mj.nv; ++d) rm.dofNames.push_back(j.name());
    rm.joints.push_back(mj);
  }

  std::set<std::string> idents;
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & b = mb.body(i);
    BodyFrame bf;
    bf.name = b.name();
    bf.ident = sanitizeIdentifier(b.name());
    while(!idents.insert(bf.ident).second) bf.ident += "_";
    bf.owner = owner[k];
    bf.X_owner_link = snapTransform(X_mb_link[k] * X_owner_mb[k]);
    bf.mass = b.inertia().mass();
    rm.totalMass += bf.mass;
    // Merge the body's inertia into its owner: I_owner += X_owner_i^T I_i X_owner_i.
    if(owner[k] >= 0)
    {
      auto & mj = rm.joints[static_cast<std::size_t>(owner[k])];
      mj.inertia = mj.inertia + X_owner_mb[k].transMul(b.inertia());
    }
    else
    {
      // Static body: X_owner_mb is X_0_i; its first moment in world is X_0_i^T applied to h.
      rm.staticMoment += X_owner_mb[k].transMul(b.inertia()).momentum();
    }
    rm.bodies.push_back(bf);
  }

  // Subtree masses, leaves up: a moving joint with a massless subtree makes H singular.
  std::vector<double> subtreeMass(rm.joints.size(), 0.0);
  for(std::size_t k = rm.joints.size(); k-- > 0;)
  {
    subtreeMass[k] += rm.joints[k].inertia.mass();
    const int p = rm.joints[k].parent;
    if(p >= 0) subtreeMass[static_cast<std::size_t>(p)] += subtreeMass[k];
  }
  for(std::size_t k = 0; k < rm.joints.size(); ++k)
    if(subtreeMass[k] <= 0.0) rm.masslessSubtrees.push_back(rm.joints[k].name);
  rm.checks = checkMassMatrix(mb);
  return rm;
}

} // namespace rbdgen
