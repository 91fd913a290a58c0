// Scene file -> Scene (docs/SCENES.md is the format's reference). One function per element; names
// are checked against the robot, which is loaded first. <simulation> is read in SceneSimulation.cpp.
#include "rbd/scene/SceneLoader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "SceneParse.h"

namespace rbd::scene
{

namespace
{

using tinyxml2::XMLElement;
using parse::Context;

void readRobot(Context & cx, const XMLElement * e, const std::string & baseDir, Scene & s)
{
  const std::string urdf = cx.rd.required(e, "", "urdf");
  cx.rd.onlyAttributes(e, urdf, {"urdf", "base", "base_link"});
  cx.rd.onlyChildren(e, urdf, {});
  const std::filesystem::path p(urdf);
  s.urdf = (p.is_absolute() || baseDir.empty() ? p : std::filesystem::path(baseDir) / p).lexically_normal().string();
  s.floatingBase = cx.rd.choice(e, urdf, "base", {"fixed", "floating"}).value_or("fixed") == "floating";
  s.baseLink = cx.rd.text(e, "base_link").value_or("");
  rbd::parsers::ParserOptions opt;
  opt.fixed = !s.floatingBase;
  opt.baseLink = s.baseLink;
  try
  {
    cx.robot = rbd::parsers::fromUrdfFile(s.urdf, opt);
  }
  catch(const std::exception & err)
  {
    cx.rd.fail(e, urdf, err.what());
  }
}

void readGravity(Context & cx, const XMLElement * e, Scene & s)
{
  cx.rd.onlyAttributes(e, "", {"enabled", "x", "y", "z"});
  cx.rd.onlyChildren(e, "", {});
  const bool enabled = cx.rd.boolean(e, "", "enabled").value_or(true);
  const auto x = cx.rd.number(e, "", "x"), y = cx.rd.number(e, "", "y"), z = cx.rd.number(e, "", "z");
  const int given = int(bool(x)) + int(bool(y)) + int(bool(z));
  if(!enabled)
  {
    if(given) cx.rd.fail(e, "", "enabled=\"false\" takes no x, y, z");
    s.gravity.reset();
    return;
  }
  if(given != 0 && given != 3) cx.rd.fail(e, "", "give all of x, y, z (or none for 0 0 -9.81)");
  if(given == 3) s.gravity = Eigen::Vector3d(*x, *y, *z);
}

void readVelocityTerms(Context & cx, const XMLElement * e, Scene & s)
{
  cx.rd.onlyAttributes(e, "", {"enabled"});
  cx.rd.onlyChildren(e, "", {});
  if(!cx.rd.text(e, "enabled")) cx.rd.fail(e, "", "missing attribute 'enabled'");
  s.velocityTerms = *cx.rd.boolean(e, "", "enabled");
}

void readJoints(Context & cx, const XMLElement * e, Scene & s)
{
  cx.rd.onlyAttributes(e, "", {"damping", "friction", "friction_velocity"});
  cx.rd.onlyChildren(e, "", {"joint", "lock"});
  const bool urdfDamping = cx.rd.choice(e, "", "damping", {"urdf", "none"}).value_or("urdf") == "urdf";
  const bool urdfFriction = cx.rd.choice(e, "", "friction", {"urdf", "none"}).value_or("urdf") == "urdf";
  s.frictionVelocity = cx.rd.nonNegative(e, "", "friction_velocity", true).value_or(s.frictionVelocity);
  // URDF <dynamics> (or none), then per-joint overrides
  s.joints.clear();
  for(const auto & j : cx.robot.mb.joints())
  {
    if(!cx.isMovable(j.name())) continue;
    JointEffects fx;
    if(auto it = cx.robot.dynamics.find(j.name()); it != cx.robot.dynamics.end())
    {
      if(urdfDamping) fx.damping = it->second.damping;
      if(urdfFriction) fx.friction = it->second.friction;
    }
    s.joints[j.name()] = fx;
  }
  std::set<std::string> overridden;
  for(const XMLElement * c = e->FirstChildElement(); c; c = c->NextSiblingElement())
  {
    const std::string name = cx.rd.required(c, "", "name");
    cx.checkMovable(c, name);
    if(std::string(c->Name()) == "joint")
    {
      cx.rd.onlyAttributes(c, name, {"name", "damping", "friction", "armature"});
      cx.rd.onlyChildren(c, name, {});
      if(!overridden.insert(name).second) cx.rd.fail(c, name, "joint given twice in <joints>");
      JointEffects & fx = s.joints[name];
      fx.damping = cx.rd.nonNegative(c, name, "damping").value_or(fx.damping);
      fx.friction = cx.rd.nonNegative(c, name, "friction").value_or(fx.friction);
      fx.armature = cx.rd.nonNegative(c, name, "armature").value_or(fx.armature);
    }
    else // lock
    {
      cx.rd.onlyAttributes(c, name, {"name", "position"});
      cx.rd.onlyChildren(c, name, {});
      if(s.locked.count(name)) cx.rd.fail(c, name, "joint locked twice");
      auto q = cx.rd.numbers(c, name, "position");
      if(!q) cx.rd.fail(c, name, "missing attribute 'position'");
      if(static_cast<int>(q->size()) != cx.params(name))
        cx.rd.fail(c, name,
                   "position has " + std::to_string(q->size()) + " values, the joint has " +
                       std::to_string(cx.params(name)) + " parameters");
      s.locked[name] = *q;
    }
  }
  for(const std::string & name : overridden)
    if(s.locked.count(name)) cx.rd.fail(e, name, "joint is both locked and given effects");
  for(const auto & [name, q] : s.locked) s.joints.erase(name);
}

void readContacts(Context & cx, const XMLElement * e, Scene & s)
{
  cx.rd.onlyAttributes(e, "", {"stiffness", "damping", "mu", "slip_velocity", "ground_height"});
  cx.rd.onlyChildren(e, "", {"point"});
  ContactModel & m = s.contactModel;
  if(!cx.rd.text(e, "stiffness")) cx.rd.fail(e, "", "missing attribute 'stiffness'");
  m.stiffness = *cx.rd.nonNegative(e, "", "stiffness", true);
  m.damping = cx.rd.nonNegative(e, "", "damping").value_or(m.damping);
  m.mu = cx.rd.nonNegative(e, "", "mu").value_or(m.mu);
  m.slipVelocity = cx.rd.nonNegative(e, "", "slip_velocity", true).value_or(m.slipVelocity);
  m.groundHeight = cx.rd.number(e, "", "ground_height").value_or(m.groundHeight);
  std::set<std::string> names;
  for(const XMLElement * c = e->FirstChildElement(); c; c = c->NextSiblingElement())
  {
    const std::string name = cx.rd.required(c, "", "name");
    cx.rd.onlyAttributes(c, name, {"name", "body", "xyz"});
    cx.rd.onlyChildren(c, name, {});
    if(!names.insert(name).second) cx.rd.fail(c, name, "contact point name given twice");
    ContactPoint p;
    p.name = name;
    p.body = cx.rd.required(c, name, "body");
    cx.checkLink(c, p.body);
    if(auto xyz = cx.rd.numbers(c, name, "xyz"))
    {
      if(xyz->size() != 3) cx.rd.fail(c, name, "xyz needs 3 values, got " + std::to_string(xyz->size()));
      p.point = Eigen::Vector3d((*xyz)[0], (*xyz)[1], (*xyz)[2]);
    }
    s.contacts.push_back(p);
  }
  if(s.contacts.empty()) cx.rd.fail(e, "", "no <point> given");
}

void readExternalWrench(Context & cx, const XMLElement * e, Scene & s)
{
  const std::string body = cx.rd.required(e, "", "body");
  cx.rd.onlyAttributes(e, body, {"body"});
  cx.rd.onlyChildren(e, body, {});
  cx.checkLink(e, body);
  for(const std::string & b : s.externalWrenches)
    if(b == body) cx.rd.fail(e, body, "external wrench on this link given twice");
  s.externalWrenches.push_back(body);
}

void readOutputs(Context & cx, const XMLElement * e, Scene & s)
{
  cx.rd.onlyAttributes(e, "", {});
  cx.rd.onlyChildren(e, "", {"pose", "jacobian", "com", "momentum", "energy", "derivatives", "kinematics"});
  for(const XMLElement * c = e->FirstChildElement(); c; c = c->NextSiblingElement())
  {
    const std::string tag = c->Name();
    if(tag == "pose" || tag == "jacobian")
    {
      const std::string body = cx.rd.required(c, "", "body");
      cx.rd.onlyAttributes(c, body, {"body"});
      cx.rd.onlyChildren(c, body, {});
      cx.checkLink(c, body);
      auto & list = tag == "pose" ? s.outputs.poses : s.outputs.jacobians;
      for(const std::string & b : list)
        if(b == body) cx.rd.fail(c, body, "output given twice");
      list.push_back(body);
      continue;
    }
    cx.rd.onlyAttributes(c, "", {});
    cx.rd.onlyChildren(c, "", {});
    bool & flag = tag == "com"           ? s.outputs.com
                  : tag == "momentum"    ? s.outputs.momentum
                  : tag == "derivatives" ? s.outputs.derivatives
                  : tag == "kinematics"  ? s.outputs.kinematics
                                         : s.outputs.energy;
    if(flag) cx.rd.fail(c, "", "output given twice");
    flag = true;
  }
}

} // namespace

Scene loadSceneString(const std::string & text, const std::string & sourceName, const std::string & baseDir)
{
  Context cx{xml::Reader(sourceName), {}};
  tinyxml2::XMLDocument doc;
  if(doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
  {
    // ErrorStr() is "Error=<name> ErrorID=<n> (<hex>) Line number=<line>[: <detail>]": keep the detail
    const std::string str = doc.ErrorStr();
    const auto at = str.find("Line number=");
    const auto colon = at == std::string::npos ? std::string::npos : str.find(": ", at);
    const std::string detail = colon == std::string::npos ? "" : str.substr(colon + 2);
    cx.rd.failAt(doc.ErrorLineNum(), "xml", "", "not well-formed XML: " + std::string(doc.ErrorName()) +
                                                    (detail.empty() ? "" : " (" + detail + ")"));
  }
  const XMLElement * root = doc.RootElement();
  if(!root || std::string(root->Name()) != "scene")
    cx.rd.failAt(root ? root->GetLineNum() : 1, root ? root->Name() : "xml", "", "the root element must be <scene>");
  Scene s;
  s.file = sourceName;
  s.name = cx.rd.text(root, "name").value_or("");
  cx.rd.onlyAttributes(root, s.name, {"name"});
  cx.rd.onlyChildren(root, s.name,
                     {"robot", "gravity", "velocity_terms", "joints", "external_wrench", "contacts", "outputs",
                      "simulation"});
  const XMLElement * robot = cx.rd.single(root, "robot");
  if(!robot) cx.rd.fail(root, s.name, "missing <robot urdf=\"...\"/>");
  readRobot(cx, robot, baseDir, s);
  if(s.name.empty()) s.name = cx.robot.name;
  // defaults from the URDF: joint effects as <joints damping="urdf" friction="urdf"/>
  if(const XMLElement * e = cx.rd.single(root, "joints")) readJoints(cx, e, s);
  else
  {
    tinyxml2::XMLDocument empty;
    readJoints(cx, empty.NewElement("joints"), s);
  }
  if(const XMLElement * e = cx.rd.single(root, "gravity")) readGravity(cx, e, s);
  if(const XMLElement * e = cx.rd.single(root, "velocity_terms")) readVelocityTerms(cx, e, s);
  for(const XMLElement * e = root->FirstChildElement("external_wrench"); e; e = e->NextSiblingElement("external_wrench"))
    readExternalWrench(cx, e, s);
  if(const XMLElement * e = cx.rd.single(root, "contacts")) readContacts(cx, e, s);
  if(const XMLElement * e = cx.rd.single(root, "outputs")) readOutputs(cx, e, s);
  if(const XMLElement * e = cx.rd.single(root, "simulation")) parse::readSimulation(cx, e, s);
  return s;
}

Scene loadScene(const std::string & path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) throw SceneError(path + ": file: cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return loadSceneString(text.str(), path, std::filesystem::path(path).parent_path().string());
}

} // namespace rbd::scene
