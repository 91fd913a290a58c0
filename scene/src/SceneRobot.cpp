// Scene -> SceneRobot: the URDF with the scene's base options, locked joints made Fixed at their
// held position (MultiBodyGraph::fixJoints keeps X_parent_child = X_joint(q) across the joint),
// per-dof joint effects and the bodies of contacts and external wrenches.
#include "rbd/scene/SceneLoader.h"

#include <rbd/FK.h>
#include <rbd/FV.h>

namespace rbd::scene
{

namespace
{

/// Rebuild mb, mbc and bodyBaseTransforms from the (edited) graph, as the loader does.
void rebuildTree(rbd::parsers::ParserResult & r, bool fixedBase)
{
  const std::string base = r.mb.body(0).name();
  r.mb = r.mbg.makeMultiBody(base, fixedBase);
  r.mbc = rbd::MultiBodyConfig(r.mb);
  r.mbc.zero(r.mb);
  rbd::forwardKinematics(r.mb, r.mbc);
  rbd::forwardVelocity(r.mb, r.mbc);
  r.bodyBaseTransforms = rbd::parsers::linkToBodyTransforms(r.mbg, base);
}

} // namespace

SceneRobot loadSceneRobot(const Scene & scene)
{
  rbd::parsers::ParserOptions opt;
  opt.fixed = !scene.floatingBase;
  opt.baseLink = scene.baseLink;
  SceneRobot out;
  try
  {
    out.robot = rbd::parsers::fromUrdfFile(scene.urdf, opt);
  }
  catch(const std::exception & e)
  {
    throw SceneError(scene.file + ": robot '" + scene.urdf + "': " + e.what());
  }
  rbd::parsers::ParserResult & r = out.robot;
  if(!scene.locked.empty())
  {
    r.mbg.fixJoints(scene.locked);
    rebuildTree(r, opt.fixed);
    for(const auto & [name, q] : scene.locked)
    {
      r.limits.lower.erase(name);
      r.limits.upper.erase(name);
      r.limits.velocity.erase(name);
      r.limits.torque.erase(name);
      r.dynamics.erase(name);
      r.mimics.erase(name);
    }
  }
  const int nv = r.mb.nrDof();
  out.damping = out.friction = out.armature = Eigen::VectorXd::Zero(nv);
  for(int i = 0; i < r.mb.nrJoints(); ++i)
  {
    auto it = scene.joints.find(r.mb.joint(i).name());
    if(it == scene.joints.end()) continue;
    const auto seg = [&](Eigen::VectorXd & v) { return v.segment(r.mb.jointPosInDof(i), r.mb.joint(i).dof()); };
    seg(out.damping).setConstant(it->second.damping);
    seg(out.friction).setConstant(it->second.friction);
    seg(out.armature).setConstant(it->second.armature);
  }
  for(const ContactPoint & c : scene.contacts) out.contactBodies.push_back(r.mb.bodyIndexByName(c.body));
  for(const std::string & b : scene.externalWrenches) out.wrenchBodies.push_back(r.mb.bodyIndexByName(b));
  return out;
}

} // namespace rbd::scene
