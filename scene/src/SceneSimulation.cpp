// The <simulation> element of a scene file: integrator, step, duration, initial state, controller.
#include <cmath>

#include "SceneParse.h"

namespace rbd::scene::parse
{

namespace
{

/// A joint of the model that a state entry may name: movable and not locked, or the floating root.
void checkStateJoint(Context & cx, const XMLElement * e, const std::string & joint, const Scene & s)
{
  if(joint != rbd::rootJointName || !s.floatingBase) cx.checkMovable(e, joint);
  if(s.locked.count(joint)) cx.rd.fail(e, joint, "joint is locked");
}

void readInitial(Context & cx, const XMLElement * e, Scene & s)
{
  const std::string joint = cx.rd.required(e, "", "joint");
  cx.rd.onlyAttributes(e, joint, {"joint", "q", "alpha"});
  cx.rd.onlyChildren(e, joint, {});
  checkStateJoint(cx, e, joint, s);
  if(s.initialQ.count(joint) || s.initialAlpha.count(joint)) cx.rd.fail(e, joint, "initial state given twice");
  const auto q = cx.rd.numbers(e, joint, "q"), alpha = cx.rd.numbers(e, joint, "alpha");
  if(!q && !alpha) cx.rd.fail(e, joint, "give q and/or alpha");
  if(q)
  {
    if(static_cast<int>(q->size()) != cx.params(joint))
      cx.rd.fail(e, joint,
                 "q has " + std::to_string(q->size()) + " values, the joint has " + std::to_string(cx.params(joint)) +
                     " parameters");
    const auto type = cx.robot.mb.joint(cx.robot.mb.jointIndexByName(joint)).type();
    if(type == rbd::Joint::Free || type == rbd::Joint::Spherical)
    {
      const double n = std::sqrt((*q)[0] * (*q)[0] + (*q)[1] * (*q)[1] + (*q)[2] * (*q)[2] + (*q)[3] * (*q)[3]);
      if(std::abs(n - 1) > 1e-3)
        cx.rd.fail(e, joint, "the quaternion qw qx qy qz has norm " + std::to_string(n) + ", expected 1");
    }
    s.initialQ[joint] = *q;
  }
  if(alpha)
  {
    if(static_cast<int>(alpha->size()) != cx.dof(joint))
      cx.rd.fail(e, joint,
                 "alpha has " + std::to_string(alpha->size()) + " values, the joint has " +
                     std::to_string(cx.dof(joint)) + " dof");
    s.initialAlpha[joint] = *alpha;
  }
}

void readController(Context & cx, const XMLElement * e, Scene & s)
{
  cx.rd.onlyAttributes(e, "", {"type", "kp", "kd"});
  cx.rd.onlyChildren(e, "", {"target"});
  Controller & c = s.controller;
  const std::string type = cx.rd.choice(e, "", "type", {"zero", "pd", "pd_gravity"}).value_or("zero");
  c.type = type == "pd"           ? Controller::Type::PdHold
           : type == "pd_gravity" ? Controller::Type::PdGravity
                                  : Controller::Type::ZeroTorque;
  c.kp = cx.rd.nonNegative(e, type, "kp").value_or(0);
  c.kd = cx.rd.nonNegative(e, type, "kd").value_or(0);
  if(c.type == Controller::Type::ZeroTorque && (cx.rd.text(e, "kp") || cx.rd.text(e, "kd") || e->FirstChildElement()))
    cx.rd.fail(e, type, "kp, kd and <target> belong to type=\"pd\" or \"pd_gravity\"");
  for(const XMLElement * t = e->FirstChildElement(); t; t = t->NextSiblingElement())
  {
    const std::string joint = cx.rd.required(t, "", "joint");
    cx.rd.onlyAttributes(t, joint, {"joint", "position"});
    cx.rd.onlyChildren(t, joint, {});
    checkStateJoint(cx, t, joint, s);
    if(cx.params(joint) != 1 || cx.dof(joint) != 1) cx.rd.fail(t, joint, "PD hold acts on 1-dof joints only");
    if(c.target.count(joint)) cx.rd.fail(t, joint, "target given twice");
    auto p = cx.rd.number(t, joint, "position");
    if(!p) cx.rd.fail(t, joint, "missing attribute 'position'");
    c.target[joint] = *p;
  }
}

} // namespace

void readSimulation(Context & cx, const XMLElement * e, Scene & s)
{
  cx.rd.onlyAttributes(e, "", {"integrator", "dt", "duration"});
  cx.rd.onlyChildren(e, "", {"initial", "controller"});
  const std::string integrator =
      cx.rd.choice(e, "", "integrator", {"semi_implicit_euler", "explicit_euler", "rk4"}).value_or("semi_implicit_euler");
  s.integrator = integrator == "rk4"              ? Integrator::RK4
                 : integrator == "explicit_euler" ? Integrator::ExplicitEuler
                                                  : Integrator::SemiImplicitEuler;
  s.dt = cx.rd.nonNegative(e, "", "dt", true).value_or(s.dt);
  s.duration = cx.rd.nonNegative(e, "", "duration", true).value_or(s.duration);
  if(s.dt > s.duration) cx.rd.fail(e, "", "dt is larger than duration");
  for(const XMLElement * c = e->FirstChildElement("initial"); c; c = c->NextSiblingElement("initial"))
    readInitial(cx, c, s);
  if(const XMLElement * c = cx.rd.single(e, "controller")) readController(cx, c, s);
}

} // namespace rbd::scene::parse
