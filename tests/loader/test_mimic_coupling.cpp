// rbd::parsers::coupleMimics: the affine map q_full = G q + o of the URDF's mimic elements, by
// hand for a chain, siblings, a mimic of a fixed joint, and the errors.
#include <gtest/gtest.h>

#include <rbd/parsers/MimicCoupling.h>
#include <rbd/parsers/urdf.h>

namespace
{

std::string link(const std::string & name)
{
  return "<link name=\"" + name + "\"><inertial><mass value=\"1\"/><inertia ixx=\"0.1\" ixy=\"0\" ixz=\"0\" iyy=\"0.1\" "
         "iyz=\"0\" izz=\"0.1\"/></inertial></link>";
}

std::string joint(const std::string & name, const std::string & type, const std::string & parent, const std::string & child,
                  const std::string & more = "")
{
  return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent + "\"/><child link=\"" + child +
         "\"/><origin xyz=\"0.1 0 0\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>" +
         more + "</joint>";
}

std::string mimic(const std::string & of, double m, double o)
{
  return "<mimic joint=\"" + of + "\" multiplier=\"" + std::to_string(m) + "\" offset=\"" + std::to_string(o) + "\"/>";
}

rbd::parsers::ParserResult load(const std::string & joints, const std::vector<std::string> & links)
{
  std::string xml = "<robot name=\"m\">" + link("base");
  for(const auto & l : links) xml += link(l);
  return rbd::parsers::fromUrdfString(xml + joints + "</robot>", {}, "m.urdf");
}

TEST(MimicCoupling, ChainSiblingsAndFixedTargets)
{
  // base -a-> A -b-> B (b mimics c), A -c-> C (c mimics a: b = 2 (-0.5 a + 0.25) + 1), A -f(fixed)-> F -g-> G (g mimics f)
  const auto robot = load(joint("a", "revolute", "base", "A") + joint("b", "prismatic", "A", "B", mimic("c", 2, 1)) +
                              joint("c", "revolute", "A", "C", mimic("a", -0.5, 0.25)) + joint("f", "fixed", "A", "F") +
                              joint("g", "revolute", "F", "G", mimic("f", 3, 0)),
                          {"A", "B", "C", "F", "G"});
  std::vector<std::string> warnings;
  const auto c = rbd::parsers::coupleMimics(robot, "m.urdf", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("joint 'g': mimics joint 'f', which is fixed"), std::string::npos) << warnings[0];
  EXPECT_EQ(c.nq, 2); // a and g
  EXPECT_EQ(c.nv, 2);
  EXPECT_EQ(c.dofJoints, (std::vector<std::string>{"a", "g"}));
  const rbd::MultiBody & mb = robot.mb;
  auto q = [&](const std::string & j) { return static_cast<std::size_t>(mb.jointPosInParam(mb.jointIndexByName(j))); };
  auto v = [&](const std::string & j) { return static_cast<std::size_t>(mb.jointPosInDof(mb.jointIndexByName(j))); };
  EXPECT_EQ(c.qSource[q("a")], 0);
  EXPECT_EQ(c.qSource[q("g")], 1);
  EXPECT_EQ(c.qSource[q("c")], 0);
  EXPECT_DOUBLE_EQ(c.qMultiplier[q("c")], -0.5);
  EXPECT_DOUBLE_EQ(c.qOffset[q("c")], 0.25);
  EXPECT_EQ(c.qSource[q("b")], 0);
  EXPECT_DOUBLE_EQ(c.qMultiplier[q("b")], -1.0);      // 2 * -0.5
  EXPECT_DOUBLE_EQ(c.qOffset[q("b")], 2 * 0.25 + 1);  // 2 * 0.25 + 1
  EXPECT_EQ(c.vSource[v("b")], 0);
  EXPECT_DOUBLE_EQ(c.vMultiplier[v("b")], -1.0);
  EXPECT_DOUBLE_EQ(c.vMultiplier[v("g")], 1.0);
  EXPECT_EQ(c.coupled.size(), 2u);
}

TEST(MimicCoupling, Errors)
{
  auto message = [](const rbd::parsers::ParserResult & r) {
    try
    {
      rbd::parsers::coupleMimics(r, "m.urdf", nullptr);
    }
    catch(const rbd::parsers::UrdfError & e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto cycle = load(joint("a", "revolute", "base", "A", mimic("b", 1, 0)) + joint("b", "revolute", "A", "B", mimic("a", 1, 0)),
                          {"A", "B"});
  EXPECT_NE(message(cycle).find("m.urdf: joint 'a': mimic cycle a -> b -> a"), std::string::npos) << message(cycle);
  const auto planar = load(joint("p", "planar", "base", "A") + joint("b", "revolute", "A", "B", mimic("p", 1, 0)), {"A", "B"});
  EXPECT_NE(message(planar).find("joint 'b': mimics joint 'p', which is not revolute"), std::string::npos) << message(planar);
  const auto self = load(joint("a", "revolute", "base", "A", mimic("a", 1, 0)), {"A"});
  EXPECT_NE(message(self).find("mimic cycle a -> a"), std::string::npos) << message(self);
}

} // namespace
