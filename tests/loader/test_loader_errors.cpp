// A corpus of broken URDFs: each throws UrdfError whose one-line message names the file, the
// element and a reason ("<file>: <element> '<name>': <reason>").
#include <gtest/gtest.h>

#include <rbd/parsers/urdf.h>

using rbd::parsers::fromUrdfString;
using rbd::parsers::ParserOptions;
using rbd::parsers::UrdfError;

namespace
{

struct BrokenCase
{
  std::string id;      ///< also the file name: broken/<id>.urdf
  std::string xml;
  std::string element; ///< expected element kind
  std::string name;    ///< expected element name
  std::string reason;  ///< expected substring of the reason
  ParserOptions opt = {};
};

const std::string triangleViolation = "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"3\"";
const std::string lim = "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>";

std::string robot(const std::string & body, const std::string & attrs = "name=\"bad\"")
{
  return "<robot " + attrs + ">" + body + "</robot>";
}
std::string link(const std::string & n, const std::string & inside = "")
{
  return "<link name=\"" + n + "\">" + inside + "</link>";
}
std::string joint(const std::string & n, const std::string & p, const std::string & c, const std::string & type = "revolute",
                  const std::string & inside = "<axis xyz=\"0 0 1\"/>" + lim)
{
  return "<joint name=\"" + n + "\" type=\"" + type + "\"><parent link=\"" + p + "\"/><child link=\"" + c + "\"/>" + inside +
         "</joint>";
}
std::string inertial(const std::string & mass, const std::string & inertia = "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"",
                     const std::string & origin = "<origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>")
{
  return "<inertial>" + origin + "<mass value=\"" + mass + "\"/><inertia " + inertia + "/></inertial>";
}

std::vector<BrokenCase> corpus()
{
  const std::string ab = link("a") + link("b");
  std::vector<BrokenCase> c{
      {"truncated", "<robot name=\"bad\"><link name=\"a\"/><joint name=\"j\" type=\"fixed\"><parent link=\"a\"/>", "xml",
       "line 1", "malformed URDF or XML"},
      {"not_xml", "this is not XML <<", "xml", "line 1", "malformed URDF or XML"},
      {"not_a_robot", "<model name=\"x\"/>", "xml", "model", "root element is not <robot>"},
      {"robot_without_name", "<robot>" + link("a") + "</robot>", "robot", "", "missing attribute 'name'"},
      {"no_link", robot(""), "robot", "bad", "no <link>"},
      {"link_without_name", robot("<link/>"), "link", "", "missing attribute 'name'"},
      {"missing_parent_link", robot(link("a") + joint("j", "ghost", "a")), "joint", "j", "parent link 'ghost' does not exist"},
      {"missing_child_link", robot(link("a") + joint("j", "a", "ghost")), "joint", "j", "child link 'ghost' does not exist"},
      {"missing_parent_element",
       robot(ab + "<joint name=\"j\" type=\"fixed\"><child link=\"b\"/></joint>"), "joint", "j", "missing <parent"},
      {"duplicate_link", robot(link("a") + link("a")), "link", "a", "duplicate link name"},
      {"duplicate_joint", robot(link("a") + link("b") + link("c") + joint("j", "a", "b") + joint("j", "a", "c")), "joint", "j",
       "duplicate joint name"},
      {"several_roots", robot(link("a") + link("b") + link("c") + joint("j", "a", "b")), "robot", "bad",
       "several root links"},
      {"cycle", robot(ab + joint("j1", "a", "b") + joint("j2", "b", "a")), "joint", "j2", "closes a kinematic cycle"},
      {"two_parents", robot(link("r") + ab + joint("j1", "r", "a") + joint("j2", "r", "b") + joint("j3", "b", "a")), "link",
       "a", "child of two joints 'j1' and 'j3'"},
      {"self_joint", robot(link("a") + joint("j", "a", "a")), "joint", "j", "to itself"},
      {"unknown_joint_type", robot(ab + joint("j", "a", "b", "hinge")), "joint", "j", "unknown joint type 'hinge'"},
      {"zero_axis", robot(ab + joint("j", "a", "b", "revolute", "<axis xyz=\"0 0 0\"/>" + lim)), "joint", "j", "zero axis"},
      {"nan_axis", robot(ab + joint("j", "a", "b", "prismatic", "<axis xyz=\"nan 0 1\"/>" + lim)), "joint", "j",
       "axis xyz=\"nan 0 1\" is not finite"},
      {"short_axis", robot(ab + joint("j", "a", "b", "revolute", "<axis xyz=\"0 1\"/>" + lim)), "joint", "j",
       "has 2 values, expected 3"},
      {"garbage_number", robot(ab + joint("j", "a", "b", "fixed", "<origin xyz=\"0 abc 0\"/>")), "joint", "j",
       "is not a list of numbers"},
      {"nan_origin", robot(ab + joint("j", "a", "b", "fixed", "<origin xyz=\"0 0 nan\" rpy=\"0 0 0\"/>")), "joint", "j",
       "origin xyz=\"0 0 nan\" is not finite"},
      {"inf_rpy", robot(ab + joint("j", "a", "b", "fixed", "<origin xyz=\"0 0 0\" rpy=\"inf 0 0\"/>")), "joint", "j",
       "origin rpy=\"inf 0 0\" is not finite"},
      {"nan_inertial_origin", robot(link("a", inertial("1", "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"",
                                                       "<origin xyz=\"nan 0 0\"/>"))),
       "link", "a", "inertial origin xyz=\"nan 0 0\" is not finite"},
      {"negative_mass", robot(link("a", inertial("-1"))), "link", "a", "negative mass -1"},
      {"nan_mass", robot(link("a", inertial("nan"))), "link", "a", "mass value=\"nan\" is not finite"},
      {"inf_mass", robot(link("a", inertial("inf"))), "link", "a", "mass value=\"inf\" is not finite"},
      {"missing_mass", robot(link("a", "<inertial><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>")),
       "link", "a", "without <mass>"},
      {"missing_inertia_value", robot(link("a", inertial("1", "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\""))), "link",
       "a", "missing attribute 'izz'"},
      {"non_psd_inertia", robot(link("a", inertial("1", "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"-0.5\""))),
       "link", "a", "not positive semi-definite"},
      {"non_psd_offdiagonal", robot(link("a", inertial("1", "ixx=\"1\" ixy=\"2\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\""))),
       "link", "a", "not positive semi-definite"},
      {"revolute_without_limit", robot(ab + joint("j", "a", "b", "revolute", "<axis xyz=\"0 0 1\"/>")), "joint", "j",
       "revolute joint without <limit>"},
      {"limits_reversed",
       robot(ab + joint("j", "a", "b", "prismatic", "<limit lower=\"1\" upper=\"-1\" effort=\"1\" velocity=\"1\"/>")), "joint",
       "j", "lower limit"},
      {"mimic_unknown_joint",
       robot(ab + joint("j", "a", "b", "revolute", lim + "<mimic joint=\"ghost\"/>")), "joint", "j",
       "mimics unknown joint 'ghost'"},
      // Passes our checks, rejected by urdfdom: the reason carries urdfdom's own message.
      {"urdfdom_rejects_version", robot(link("a"), "name=\"bad\" version=\"1.x\""), "robot", "bad",
       "malformed URDF or XML (urdfdom:"},
  };
  BrokenCase triangle{"triangle_inequality_strict", robot(link("a", inertial("1", triangleViolation))), "link", "a",
                      "violates the triangle inequality"};
  triangle.opt.strictInertia = true;
  c.push_back(triangle);
  BrokenCase base{"unknown_base_link", robot(ab + joint("j", "a", "b")), "link", "nope", "unknown base link"};
  base.opt.baseLink = "nope";
  c.push_back(base);
  BrokenCase filtered{"unknown_filtered_link", robot(ab + joint("j", "a", "b")), "link", "zzz", "unknown filtered link"};
  filtered.opt.filteredLinks = {"zzz"};
  c.push_back(filtered);
  BrokenCase filteredBase{"filtered_base_link", robot(ab + joint("j", "a", "b")), "link", "a", "base link cannot be filtered"};
  filteredBase.opt.filteredLinks = {"a"};
  c.push_back(filteredBase);
  return c;
}

} // namespace

TEST(LoaderErrors, BrokenCorpusThrowsOneLineUrdfError)
{
  for(const BrokenCase & bc : corpus())
  {
    SCOPED_TRACE(bc.id);
    const std::string file = "broken/" + bc.id + ".urdf";
    try
    {
      fromUrdfString(bc.xml, bc.opt, file);
      ADD_FAILURE() << "no exception for " << bc.id;
    }
    catch(const UrdfError & e)
    {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(file + ": " + bc.element + " '" + bc.name + "': ", 0), 0u) << what;
      EXPECT_NE(what.find(bc.reason), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      EXPECT_EQ(e.file(), file);
      EXPECT_EQ(e.element(), bc.element);
      EXPECT_EQ(e.name(), bc.name);
    }
  }
}

// The same corpus, fixed into valid URDFs by one edit each, loads: the checks are not too eager.
TEST(LoaderErrors, ValidNeighboursLoad)
{
  const std::string ab = link("a") + link("b");
  EXPECT_NO_THROW(fromUrdfString(robot(ab + joint("j", "a", "b", "revolute", "<axis xyz=\"0 0 1e-3\"/>" + lim))));
  EXPECT_NO_THROW(fromUrdfString(robot(ab + joint("j", "a", "b", "continuous", "<axis xyz=\"0 0 1\"/>"))));
  EXPECT_NO_THROW(fromUrdfString(robot(ab + joint("j", "a", "b", "fixed", "<origin xyz=\"+1 -2e-3 .5\"/>"))));
  // Zero mass, a rod (moments 0, 1, 1: triangle equality) and a disc (1, 1, 2) are all valid.
  EXPECT_NO_THROW(fromUrdfString(robot(link("a", inertial("0", "ixx=\"0\" ixy=\"0\" ixz=\"0\" iyy=\"0\" iyz=\"0\" izz=\"0\"")))));
  EXPECT_NO_THROW(fromUrdfString(robot(link("a", inertial("1", "ixx=\"0\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"")))));
  EXPECT_NO_THROW(fromUrdfString(robot(link("a", inertial("1", "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"2\"")))));
  // Triangle-inequality violations are warnings unless strictInertia.
  const auto r = fromUrdfString(robot(link("a", inertial("1", triangleViolation))), {}, "tri.urdf");
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].rfind("tri.urdf: link 'a': inertia violates the triangle inequality", 0), 0u) << r.warnings[0];
  // Any link as the base.
  ParserOptions opt;
  opt.baseLink = "b";
  EXPECT_NO_THROW(fromUrdfString(robot(ab + joint("j", "a", "b")), opt));
}

TEST(LoaderErrors, MissingFileNamesThePath)
{
  try
  {
    rbd::parsers::fromUrdfFile("/nonexistent/dir/robot.urdf");
    ADD_FAILURE() << "no exception";
  }
  catch(const UrdfError & e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/dir/robot.urdf: file '/nonexistent/dir/robot.urdf': ", 0), 0u)
        << e.what();
  }
}
