// URDF loader: checked text -> urdfdom model -> rbd::MultiBodyGraph -> MultiBody (see urdf.h).
#include <rbd/parsers/urdf.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <mutex>
#include <sstream>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <rbd/FK.h>
#include <rbd/FV.h>

#include "UrdfCheck.h"

namespace rbd
{
namespace parsers
{
namespace
{

constexpr double inf = std::numeric_limits<double>::infinity();

/// Collects urdfdom's console_bridge messages instead of printing them.
class CaptureErrors : public console_bridge::OutputHandler
{
public:
  void log(const std::string & text, console_bridge::LogLevel level, const char *, int) override
  {
    if(level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR)
    {
      if(first.empty()) first = text;
    }
    else if(level == console_bridge::CONSOLE_BRIDGE_LOG_WARN) warnings.push_back(text);
  }
  std::string first;
  std::vector<std::string> warnings;
};

/// urdfdom's parser, its messages captured (console_bridge's handler is global: one at a time).
urdf::ModelInterfaceSharedPtr parseWithUrdfdom(const std::string & xml, std::string & error,
                                               std::vector<std::string> & warnings)
{
  static std::mutex m;
  std::lock_guard<std::mutex> lock(m);
  CaptureErrors capture;
  console_bridge::useOutputHandler(&capture);
  urdf::ModelInterfaceSharedPtr model;
  try
  {
    model = urdf::parseURDF(xml);
  }
  catch(const std::exception & e)
  {
    capture.first = e.what();
  }
  console_bridge::restorePreviousOutputHandler();
  error = capture.first;
  warnings = capture.warnings;
  return model;
}

/// Usual right-handed rotation of a urdfdom pose (child frame in the parent).
Eigen::Matrix3d rotation(const urdf::Rotation & r)
{
  return Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
}

/// sva transform from the parent frame to the pose's frame: E = R^T, r = xyz.
sva::PTransformd toPTransform(const urdf::Pose & p)
{
  return sva::PTransformd(Eigen::Matrix3d(rotation(p.rotation).transpose()),
                          Eigen::Vector3d(p.position.x, p.position.y, p.position.z));
}

/// Spatial inertia at the link origin, in link coordinates, from the URDF <inertial>:
/// I_o = R I_c R^T + m c^ c^T (parallel axis), h = m c, with R the inertial frame's rotation
/// in the link and c its origin (the centre of mass).
sva::RBInertiad toRBInertia(const urdf::InertialSharedPtr & in)
{
  if(!in) return sva::RBInertiad(0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
  Eigen::Matrix3d Ic;
  Ic << in->ixx, in->ixy, in->ixz, in->ixy, in->iyy, in->iyz, in->ixz, in->iyz, in->izz;
  const Eigen::Vector3d c(in->origin.position.x, in->origin.position.y, in->origin.position.z);
  const Eigen::Matrix3d Io = sva::inertiaToOrigin(Ic, in->mass, c, rotation(in->origin.rotation));
  return sva::RBInertiad(in->mass, in->mass * c, Io);
}

rbd::Joint toJoint(const urdf::Joint & j)
{
  const Eigen::Vector3d axis(j.axis.x, j.axis.y, j.axis.z);
  switch(j.type)
  {
    case urdf::Joint::REVOLUTE:
    case urdf::Joint::CONTINUOUS: return rbd::Joint(rbd::Joint::Rev, axis, true, j.name);
    case urdf::Joint::PRISMATIC: return rbd::Joint(rbd::Joint::Prism, axis, true, j.name);
    case urdf::Joint::PLANAR: return rbd::Joint(rbd::Joint::Planar, axis, true, j.name);
    case urdf::Joint::FLOATING: return rbd::Joint(rbd::Joint::Free, true, j.name);
    case urdf::Joint::FIXED: return rbd::Joint(rbd::Joint::Fixed, true, j.name);
    default: throw std::logic_error("unknown joint type"); // excluded by checkUrdf
  }
}

/// Limits of one (non-Fixed) joint: position bounds only for revolute and prismatic.
void addLimits(const urdf::Joint & uj, const rbd::Joint & j, Limits & limits)
{
  const auto np = static_cast<std::size_t>(j.params()), nd = static_cast<std::size_t>(j.dof());
  const bool bounded = uj.type == urdf::Joint::REVOLUTE || uj.type == urdf::Joint::PRISMATIC;
  const auto & l = uj.limits;
  limits.lower[uj.name].assign(np, bounded && l ? l->lower : -inf);
  limits.upper[uj.name].assign(np, bounded && l ? l->upper : inf);
  limits.velocity[uj.name].assign(nd, l ? l->velocity : inf);
  limits.torque[uj.name].assign(nd, l ? l->effort : inf);
}

/// A floating base on a URDF that has its own: the root link is massless (no mass, no inertia) and
/// its only joint is `floating`. Returns that joint, or nullptr.
const urdf::Joint * ownFloatingJoint(const urdf::ModelInterface & model, const std::string & rootLink)
{
  const auto link = model.links_.find(rootLink);
  if(link == model.links_.end() || !link->second) return nullptr;
  const urdf::InertialSharedPtr & in = link->second->inertial;
  if(in && (in->mass != 0 || in->ixx != 0 || in->iyy != 0 || in->izz != 0 || in->ixy != 0 || in->ixz != 0 || in->iyz != 0))
    return nullptr;
  const urdf::Joint * only = nullptr;
  for(const auto & [name, j] : model.joints_)
  {
    if(!j || (j->parent_link_name != rootLink && j->child_link_name != rootLink)) continue;
    if(only) return nullptr; // more than one joint at the root link
    only = j.get();
  }
  return only && only->type == urdf::Joint::FLOATING && only->parent_link_name == rootLink ? only : nullptr;
}

} // namespace

std::map<std::string, sva::PTransformd> linkToBodyTransforms(const MultiBodyGraph & mbg, const std::string & base)
{
  std::map<std::string, sva::PTransformd> out = mbg.bodiesBaseTransform(base);
  for(auto & entry : out) entry.second = entry.second.inv();
  return out;
}

ParserResult fromUrdfString(const std::string & xml, const ParserOptions & opt, const std::string & sourceName)
{
  const detail::CheckedUrdf checked = detail::checkUrdf(xml, sourceName, opt);
  std::string urdfdomError;
  std::vector<std::string> urdfdomWarnings;
  const urdf::ModelInterfaceSharedPtr model = parseWithUrdfdom(xml, urdfdomError, urdfdomWarnings);
  if(!model)
    throw UrdfError(sourceName, "robot", checked.robotName,
                    "malformed URDF or XML (urdfdom: " + (urdfdomError.empty() ? "no detail" : urdfdomError) + ")");

  ParserResult res;
  res.name = model->getName();
  res.warnings = checked.warnings;
  for(const std::string & w : urdfdomWarnings)
    res.warnings.push_back(sourceName + ": robot '" + res.name + "': urdfdom: " + w);

  // The names our checker read must be the ones urdfdom read: the two XML parsers differ on
  // malformed entity references such as name="a&b" (found by the fuzzer).
  auto inModel = [&](const auto & map, const std::string & element, const std::string & name) -> const auto & {
    const auto it = map.find(name);
    if(it == map.end() || !it->second)
      throw UrdfError(sourceName, element, name,
                      "name read differently by urdfdom (an '&' that is not a valid entity reference, or another XML error in it?)");
    return *it->second;
  };
  // Bodies and joints in document order; a body frame is its link frame.
  for(const std::string & name : checked.links) res.mbg.addBody(rbd::Body(toRBInertia(inModel(model->links_, "link", name).inertial), name));
  for(const std::string & name : checked.joints)
  {
    const urdf::Joint & uj = inModel(model->joints_, "joint", name);
    // An <axis> whose xyz attribute urdfdom did not read (misspelt: found by the fuzzer) is zero.
    const bool hasAxis = uj.type == urdf::Joint::REVOLUTE || uj.type == urdf::Joint::CONTINUOUS
                         || uj.type == urdf::Joint::PRISMATIC || uj.type == urdf::Joint::PLANAR;
    const Eigen::Vector3d axis(uj.axis.x, uj.axis.y, uj.axis.z);
    if(hasAxis && !(axis.allFinite() && axis.norm() > 0.0))
      throw UrdfError(sourceName, "joint", uj.name, "zero axis (is the xyz attribute of <axis> spelt right?)");
    res.mbg.addJoint(toJoint(uj));
    res.mbg.linkBodies(uj.parent_link_name, toPTransform(uj.parent_to_joint_origin_transform), uj.child_link_name,
                       sva::PTransformd::Identity(), uj.name);
  }

  // A floating base on a URDF with its own floating joint under a massless root link (`world`)
  // would stack two free joints (a singular mass matrix): the URDF's joint is the floating base.
  std::string base = opt.baseLink.empty() ? checked.rootLink : opt.baseLink;
  if(!opt.fixed && base == checked.rootLink)
    if(const urdf::Joint * fj = ownFloatingJoint(*model, checked.rootLink))
    {
      base = fj->child_link_name;
      res.mbg.removeJoint(base, fj->name); // takes the root link away with it
      const urdf::Pose & o = fj->parent_to_joint_origin_transform;
      const bool offset = o.position.x != 0 || o.position.y != 0 || o.position.z != 0 || o.rotation.w != 1;
      res.warnings.push_back(
          sourceName + ": joint '" + fj->name + "': floating joint under the massless root link '" + checked.rootLink +
          "': with a floating base this would stack two free joints (a singular mass matrix), so the URDF's floating joint "
          "is the floating base: the tree is rooted at link '" + base + "' by the free joint 'Root', link '" +
          checked.rootLink + "' and joint '" + fj->name + "' are dropped" +
          (offset ? " (and the joint's <origin>: q of 'Root' is the pose of '" + base + "' in the world)" : ""));
    }

  // Filtered links: drop (or merge into the parent body) each subtree, seen from the base.
  for(const std::string & f : opt.filteredLinks)
  {
    if(!res.mbg.hasBody(f)) continue; // already gone with a filtered ancestor
    const std::string joint = res.mbg.predecessorJoint(base).at(f);
    if(opt.removeFilteredLinks) res.mbg.removeJoint(base, joint);
    else res.mbg.mergeSubBodies(base, joint, {});
  }

  res.mb = res.mbg.makeMultiBody(base, opt.fixed);
  res.mbc = rbd::MultiBodyConfig(res.mb);
  res.mbc.zero(res.mb);
  rbd::forwardKinematics(res.mb, res.mbc);
  rbd::forwardVelocity(res.mb, res.mbc);
  res.bodyBaseTransforms = linkToBodyTransforms(res.mbg, base);

  // Limits, dynamics and mimics of the joints kept in the model.
  for(const rbd::Joint & j : res.mb.joints())
  {
    if(j.name() == rootJointName) continue;
    const urdf::Joint & uj = *model->joints_.at(j.name());
    if(j.type() != rbd::Joint::Fixed) addLimits(uj, j, res.limits);
    if(uj.dynamics) res.dynamics[j.name()] = JointDynamics{uj.dynamics->damping, uj.dynamics->friction};
    if(uj.mimic) res.mimics[j.name()] = Mimic{uj.mimic->joint_name, uj.mimic->multiplier, uj.mimic->offset};
  }
  return res;
}

ParserResult fromUrdfFile(const std::string & path, const ParserOptions & opt)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) throw UrdfError(path, "file", path, "cannot open the file for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  return fromUrdfString(ss.str(), opt, path);
}

} // namespace parsers
} // namespace rbd
