#include "info.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/parsers/MimicCoupling.h>

#include "model/MassMatrixChecks.h"

namespace rbdgen
{
namespace
{

std::string axisText(const rbd::Joint & j)
{
  switch(j.type())
  {
    case rbd::Joint::Rev:
    case rbd::Joint::Prism:
    case rbd::Joint::Cylindrical:
    case rbd::Joint::Planar:
      return fmt::format(" axis ({:g} {:g} {:g})", j.axis().x(), j.axis().y(), j.axis().z());
    default:
      return "";
  }
}

// One line per body, indented by depth: "body  <- joint (Type, axis, dof) mass".
void printTree(std::ostream & os, const rbd::MultiBody & mb)
{
  std::vector<int> depth(static_cast<std::size_t>(mb.nrBodies()), 0);
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const int p = mb.parent(i);
    depth[static_cast<std::size_t>(i)] = p < 0 ? 0 : depth[static_cast<std::size_t>(p)] + 1;
    const auto & j = mb.joint(i);
    fmt::print(os, "  {:{}}{}  <- {} ({}{}{}, dof {}) mass {:.4g} kg\n", "", 2 * depth[static_cast<std::size_t>(i)],
               mb.body(i).name(), j.name(), rbd::jointTypeName(j.type()), axisText(j), j.forward() ? "" : ", backward",
               j.dof(), mb.body(i).inertia().mass());
  }
}

/// Unit of generalized force k of joint j: N m for a rotation, N for a translation.
const char * torqueUnit(const rbd::Joint & j, std::size_t k)
{
  switch(j.type())
  {
    case rbd::Joint::Prism: return "N";
    case rbd::Joint::Cylindrical: return k == 0 ? "N m" : "N";
    case rbd::Joint::Planar: return k == 0 ? "N m" : "N";
    case rbd::Joint::Free: return k < 3 ? "N m" : "N";
    default: return "N m"; // Rev, Spherical
  }
}

} // namespace

void printInfo(std::ostream & os, const rbd::parsers::ParserResult & robot, const std::string & source)
{
  const rbd::MultiBody & mb = robot.mb;
  double mass = 0;
  for(const auto & b : mb.bodies()) mass += b.inertia().mass();
  fmt::print(os, "robot '{}': {} bodies, {} joints, nq = {}, nv = {}, total mass {:.4g} kg\n", robot.name,
             mb.nrBodies(), mb.nrJoints(), mb.nrParams(), mb.nrDof(), mass);
  fmt::print(os, "tree (body <- joint):\n");
  printTree(os, mb);
  for(const auto & w : robot.warnings) fmt::print(os, "warning: {}\n", w);
  std::vector<std::string> mimicWarnings;
  const rbd::parsers::MimicCoupling coupling = rbd::parsers::coupleMimics(robot, source, &mimicWarnings);
  for(const auto & w : mimicWarnings) fmt::print(os, "warning: {}\n", w);
  if(!coupling.empty())
  {
    fmt::print(os, "mimic joints coupled (generate's default): nq = {}, nv = {}\n", coupling.nq, coupling.nv);
    for(const auto & c : coupling.coupled) fmt::print(os, "  {}\n", c);
  }
  const MassMatrixReport checks = checkMassMatrix(mb);
  if(checks.smallest.joint.empty()) fmt::print(os, "mass matrix at q = 0: M = {:.4g} kg, L = {:.3g} m\n", checks.totalMass, checks.length);
  else
    fmt::print(os, "mass matrix at q = 0: M = {:.4g} kg, L = {:.3g} m, smallest effective inertia S^T Ic S / {} = {:.2g} "
                   "(joint '{}', dof {}; warning below {:g})\n",
               checks.totalMass, checks.length, checks.smallest.rotational ? "(M L^2)" : "M", checks.smallest.ratio,
               checks.smallest.joint, checks.smallest.dof, kNegligibleRatio);
  for(const auto & w : checks.messages(source)) fmt::print(os, "warning: {}\n", w);

  // Gravity torques at the zero configuration: inverse dynamics with alpha = alphaD = 0.
  rbd::MultiBodyConfig mbc(mb);
  mbc.zero(mb);
  rbd::forwardKinematics(mb, mbc);
  rbd::forwardVelocity(mb, mbc);
  rbd::InverseDynamics id(mb);
  id.inverseDynamics(mb, mbc);
  fmt::print(os, "inverse dynamics at q = 0, alpha = alphaD = 0 (gravity 9.81 m/s^2 along -z):\n");
  for(int i = 0; i < mb.nrJoints(); ++i)
    for(std::size_t k = 0; k < mbc.jointTorque[static_cast<std::size_t>(i)].size(); ++k)
      fmt::print(os, "  tau[{}][{}] = {:+.6f} {}\n", mb.joint(i).name(), k, mbc.jointTorque[static_cast<std::size_t>(i)][k],
                 torqueUnit(mb.joint(i), k));
}

} // namespace rbdgen
