#include <rbd/parsers/MimicCoupling.h>

#include <cmath>
#include <map>
#include <sstream>

namespace rbd::parsers
{

namespace
{

bool oneDof(const rbd::Joint & j)
{
  return j.type() == rbd::Joint::Rev || j.type() == rbd::Joint::Prism;
}

/// The shortest text that reads back as x.
std::string number(double x)
{
  for(int p = 1;; ++p)
  {
    std::ostringstream os;
    os.precision(p);
    os << x;
    if(p >= 17 || std::stod(os.str()) == x) return os.str();
  }
}

/// q_j = multiplier * q_root + offset, root an independent joint.
struct Affine
{
  std::string root;
  double multiplier = 1, offset = 0;
};

} // namespace

MimicCoupling independentJoints(const rbd::MultiBody & mb)
{
  MimicCoupling c;
  c.nq = mb.nrParams();
  c.nv = mb.nrDof();
  for(int k = 0; k < c.nq; ++k) c.qSource.push_back(k);
  for(int k = 0; k < c.nv; ++k) c.vSource.push_back(k);
  c.qMultiplier.assign(static_cast<std::size_t>(c.nq), 1.0);
  c.qOffset.assign(static_cast<std::size_t>(c.nq), 0.0);
  c.vMultiplier.assign(static_cast<std::size_t>(c.nv), 1.0);
  for(const rbd::Joint & j : mb.joints())
    for(int d = 0; d < j.dof(); ++d) c.dofJoints.push_back(j.name());
  return c;
}

MimicCoupling coupleMimics(const ParserResult & robot, const std::string & sourceName, std::vector<std::string> * warnings)
{
  const rbd::MultiBody & mb = robot.mb;
  auto fail = [&](const std::string & joint, const std::string & reason) { throw UrdfError(sourceName, "joint", joint, reason); };

  // The mimic joints that move (a fixed one has no coordinate), checked one by one.
  std::map<std::string, Mimic> moving;
  for(const auto & [name, m] : robot.mimics)
  {
    if(!mb.hasJoint(name) || mb.joint(mb.jointIndexByName(name)).type() == rbd::Joint::Fixed) continue;
    if(!oneDof(mb.joint(mb.jointIndexByName(name))))
      fail(name, "mimic joint must be revolute, continuous or prismatic to be coupled");
    if(!mb.hasJoint(m.joint) || mb.joint(mb.jointIndexByName(m.joint)).type() == rbd::Joint::Fixed)
    {
      if(warnings)
        warnings->push_back(sourceName + ": joint '" + name + "': mimics joint '" + m.joint +
                            "', which is fixed (no coordinate to follow): kept as an independent joint with its own dof");
      continue;
    }
    if(!oneDof(mb.joint(mb.jointIndexByName(m.joint))))
      fail(name, "mimics joint '" + m.joint + "', which is not revolute, continuous or prismatic");
    moving[name] = m;
  }

  // Chains compose: q_a = m_a (m_b q_c + o_b) + o_a; a cycle is an error.
  std::map<std::string, Affine> resolved;
  for(const auto & entry : moving)
  {
    Affine a{entry.first, 1, 0};
    std::vector<std::string> chain{entry.first};
    while(moving.count(a.root))
    {
      const Mimic & m = moving.at(a.root);
      a = Affine{m.joint, a.multiplier * m.multiplier, a.multiplier * m.offset + a.offset};
      for(const std::string & seen : chain)
        if(seen == a.root)
        {
          std::string path;
          for(const std::string & s : chain) path += s + " -> ";
          fail(entry.first, "mimic cycle " + path + a.root + ": no joint of the cycle is independent");
        }
      chain.push_back(a.root);
    }
    resolved[entry.first] = a;
  }

  // The coupled coordinates: every joint's but the mimics', in MultiBody order.
  MimicCoupling c;
  std::vector<int> coupledQ(mb.joints().size(), -1), coupledV(mb.joints().size(), -1);
  for(std::size_t i = 0; i < mb.joints().size(); ++i)
  {
    const rbd::Joint & j = mb.joints()[i];
    if(resolved.count(j.name())) continue;
    coupledQ[i] = c.nq;
    coupledV[i] = c.nv;
    c.nq += j.params();
    c.nv += j.dof();
    for(int d = 0; d < j.dof(); ++d) c.dofJoints.push_back(j.name());
  }
  for(std::size_t i = 0; i < mb.joints().size(); ++i)
  {
    const rbd::Joint & j = mb.joints()[i];
    const auto it = resolved.find(j.name());
    if(it == resolved.end())
    {
      for(int k = 0; k < j.params(); ++k) c.qSource.push_back(coupledQ[i] + k), c.qMultiplier.push_back(1), c.qOffset.push_back(0);
      for(int k = 0; k < j.dof(); ++k) c.vSource.push_back(coupledV[i] + k), c.vMultiplier.push_back(1);
      continue;
    }
    const Affine & a = it->second;
    const std::size_t root = static_cast<std::size_t>(mb.jointIndexByName(a.root));
    c.qSource.push_back(coupledQ[root]), c.qMultiplier.push_back(a.multiplier), c.qOffset.push_back(a.offset);
    c.vSource.push_back(coupledV[root]), c.vMultiplier.push_back(a.multiplier);
    c.coupled.push_back(j.name() + " = " + number(a.multiplier) + " * " + a.root + (a.offset < 0 ? " - " : " + ") +
                        number(std::abs(a.offset)));
  }
  return c;
}

} // namespace rbd::parsers
