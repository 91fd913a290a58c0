#pragma once
// Internal to the scene parser: the state of one parse (reader + the robot for name checks) and
// the readers of the elements that live in their own file.

#include <set>
#include <string>

#include <rbd/parsers/urdf.h>

#include "SceneXml.h"
#include "rbd/scene/Scene.h"

namespace rbd::scene::parse
{

using tinyxml2::XMLElement;

/// The parse of one file: the reader (file name, errors), the robot for the name checks.
struct Context
{
  xml::Reader rd;
  rbd::parsers::ParserResult robot;

  /// A movable joint of the robot (not fixed, not the root joint).
  bool isMovable(const std::string & joint) const
  {
    return robot.mb.hasJoint(joint) && joint != rbd::rootJointName &&
           robot.mb.joint(robot.mb.jointIndexByName(joint)).type() != rbd::Joint::Fixed;
  }
  void checkMovable(const XMLElement * e, const std::string & joint) const
  {
    if(isMovable(joint)) return;
    if(robot.mbg.hasJoint(joint)) rd.fail(e, joint, "joint is fixed in the robot");
    rd.fail(e, joint, "no joint of that name in robot '" + robot.name + "'");
  }
  void checkLink(const XMLElement * e, const std::string & link) const
  {
    if(!robot.mb.hasBody(link)) rd.fail(e, link, "no link of that name in robot '" + robot.name + "'");
  }
  /// Parameter / dof counts of a joint of the model (the root joint included).
  int params(const std::string & joint) const { return robot.mb.joint(robot.mb.jointIndexByName(joint)).params(); }
  int dof(const std::string & joint) const { return robot.mb.joint(robot.mb.jointIndexByName(joint)).dof(); }
};

/// <simulation>: integrator, dt, duration, <initial>, <controller> (SceneSimulation.cpp).
void readSimulation(Context & cx, const XMLElement * e, Scene & s);

} // namespace rbd::scene::parse
