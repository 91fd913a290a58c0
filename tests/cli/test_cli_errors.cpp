// rbdgen on bad input: every failure exits non-zero with exactly one line on stderr naming the
// file, the element (where there is one) and the reason, and writes nothing: no file or directory
// appears, and a good dynamics.hpp generated earlier into the same place stays byte-identical.
#include <functional>
#include <regex>

#include "CliRun.h"

namespace clitest
{
namespace
{

using Args = std::function<std::vector<std::string>(const std::string & outDir)>;

::testing::AssertionResult mentionsAll(const std::string & err, const std::vector<std::string> & needles)
{
  for(const auto & n : needles)
    if(err.find(n) == std::string::npos) return ::testing::AssertionFailure() << "'" << n << "' not in: " << err;
  return ::testing::AssertionSuccess();
}

/// Run a failing generate twice: into a fresh output directory (which must not appear), and into
/// one holding a good robot/dynamics.hpp from pendulum.urdf (which must be left as it was).
void expectFailsCleanly(const fs::path & dir, const Args & args, const std::vector<std::string> & needles)
{
  // (a) fresh output directory.
  const std::vector<std::string> before = listTree(dir);
  const Result r = rbdgen(args("out_fresh"), dir);
  EXPECT_TRUE(isOneLineError(r));
  EXPECT_TRUE(mentionsAll(r.err, needles));
  EXPECT_EQ(listTree(dir), before) << "something was created";

  // (b) a previous good header in the same place (namespace robot).
  const fs::path pendulum = fs::path(RBDGEN_SOURCE_DIR) / "robots" / "pendulum.urdf";
  ASSERT_EQ(rbdgen({"generate", pendulum.string(), "--out", "out_prev", "--namespace", "robot"}, dir).code, 0);
  const fs::path header = dir / "out_prev" / "robot" / "dynamics.hpp";
  const std::string good = readFile(header);
  const auto old = fs::last_write_time(header) - std::chrono::hours(48);
  fs::last_write_time(header, old);
  const std::vector<std::string> withGood = listTree(dir);
  const Result r2 = rbdgen(args("out_prev"), dir);
  EXPECT_TRUE(isOneLineError(r2));
  EXPECT_TRUE(mentionsAll(r2.err, needles));
  EXPECT_EQ(listTree(dir), withGood) << "something was created";
  EXPECT_TRUE(readFile(header) == good) << "the previous header was changed";
  EXPECT_TRUE(fs::last_write_time(header) == old) << "the previous header was rewritten";
  fs::remove_all(dir / "out_prev");
}

// ---------------------------------------------------------------------------------------------
// The corpus tests/cli/bad/*.urdf

struct BadFile
{
  std::string file;
  std::vector<std::string> needles; ///< element and reason the message must contain
};

std::ostream & operator<<(std::ostream & os, const BadFile & b)
{
  return os << b.file;
}

class BadUrdf : public CliTest, public ::testing::WithParamInterface<BadFile>
{
};

TEST_P(BadUrdf, GenerateFailsCleanly)
{
  const fs::path urdf = fs::path(RBDGEN_CLI_BAD_DIR) / GetParam().file;
  ASSERT_TRUE(fs::is_regular_file(urdf));
  std::vector<std::string> needles = GetParam().needles;
  needles.push_back(GetParam().file);
  expectFailsCleanly(dir(), [&](const std::string & out) {
    return std::vector<std::string>{"generate", urdf.string(), "--out", out, "--namespace", "robot"};
  }, needles);
}

TEST_P(BadUrdf, InfoFailsWithOneLine)
{
  const fs::path urdf = fs::path(RBDGEN_CLI_BAD_DIR) / GetParam().file;
  const Result r = rbdgen({"info", urdf.string()}, dir());
  EXPECT_TRUE(isOneLineError(r));
  EXPECT_TRUE(mentionsAll(r.err, GetParam().needles));
  EXPECT_NE(r.err.find(GetParam().file), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Corpus, BadUrdf,
    ::testing::Values(BadFile{"malformed_xml.urdf", {"xml", "line 4", "malformed"}},
                      BadFile{"missing_link.urdf", {"joint 'elbow'", "'forearm' does not exist"}},
                      BadFile{"duplicate_link.urdf", {"link 'upper_arm'", "duplicate"}},
                      BadFile{"duplicate_joint.urdf", {"joint 'shoulder'", "duplicate"}},
                      BadFile{"cycle.urdf", {"joint '", "cycle"}},
                      BadFile{"several_roots.urdf", {"robot 'several_roots'", "root", "'base'", "'floating_box'"}},
                      BadFile{"unknown_joint_type.urdf", {"joint 'shoulder'", "unknown joint type 'hinge'"}},
                      BadFile{"zero_axis.urdf", {"joint 'shoulder'", "zero axis"}},
                      BadFile{"nan_axis.urdf", {"joint 'shoulder'", "axis", "not finite"}},
                      BadFile{"negative_mass.urdf", {"link 'upper_arm'", "negative mass"}},
                      BadFile{"nan_mass.urdf", {"link 'upper_arm'", "mass", "not finite"}},
                      BadFile{"non_pd_inertia.urdf", {"link 'upper_arm'", "inertia", "not positive"}},
                      BadFile{"nan_origin.urdf", {"joint 'shoulder'", "origin", "not finite"}},
                      // issue 5: the rest of the corpus
                      BadFile{"truncated.urdf", {"xml", "malformed"}},
                      BadFile{"missing_parent.urdf", {"joint 'elbow'", "parent link 'forearm' does not exist"}},
                      BadFile{"missing_parent_element.urdf", {"joint 'elbow'", "missing <parent"}},
                      BadFile{"two_parents.urdf", {"link 'upper_arm'", "child of two joints"}},
                      BadFile{"self_joint.urdf", {"joint 'elbow'", "to itself"}},
                      BadFile{"no_link.urdf", {"robot 'no_link'", "no <link>"}},
                      BadFile{"not_a_robot.urdf", {"xml 'sdf'", "root element is not <robot>"}},
                      BadFile{"robot_without_name.urdf", {"robot ''", "missing attribute 'name'"}},
                      BadFile{"inf_mass.urdf", {"link 'upper_arm'", "mass", "not finite"}},
                      BadFile{"inf_rpy.urdf", {"joint 'shoulder'", "origin rpy", "not finite"}},
                      BadFile{"nan_inertia.urdf", {"link 'upper_arm'", "inertia", "not finite"}},
                      BadFile{"nan_limit.urdf", {"joint 'shoulder'", "limit", "not finite"}},
                      BadFile{"nan_damping.urdf", {"joint 'shoulder'", "dynamics", "not finite"}},
                      BadFile{"negative_inertia.urdf", {"link 'upper_arm'", "not positive semi-definite"}},
                      BadFile{"overflow_number.urdf", {"joint 'shoulder'", "1e400", "not a list of numbers"}},
                      BadFile{"garbage_number.urdf", {"joint 'shoulder'", "0.1m", "not a list of numbers"}},
                      BadFile{"huge_mass.urdf", {"link 'upper_arm'", "mass", "1e308", "out of range"}},
                      BadFile{"huge_origin.urdf", {"joint 'shoulder'", "origin", "1e300", "out of range"}},
                      BadFile{"huge_axis.urdf", {"joint 'shoulder'", "axis", "out of range"}},
                      BadFile{"tiny_axis.urdf", {"joint 'shoulder'", "zero axis"}},
                      BadFile{"revolute_without_limit.urdf", {"joint 'shoulder'", "without <limit>"}},
                      BadFile{"limits_reversed.urdf", {"joint 'shoulder'", "lower limit"}},
                      BadFile{"mimic_unknown.urdf", {"joint 'shoulder'", "mimics unknown joint 'ghost'"}},
                      BadFile{"spherical_joint.urdf", {"joint 'shoulder'", "unknown joint type 'spherical'"}},
                      BadFile{"reserved_root_joint.urdf", {"joint 'Root'", "reserved"}},
                      BadFile{"control_char_name.urdf", {"link 'upper", "control character"}},
                      // found by fuzz/fuzz_urdf: <axis Xyz="..."/> leaves the axis zero in urdfdom
                      BadFile{"misspelt_axis_attribute.urdf", {"joint 'joint2'", "zero axis"}},
                      // found by fuzz/fuzz_urdf: urdfdom's XML parser reads name="joint&2" differently
                      BadFile{"ampersand_name.urdf", {"joint 'joint&2'", "read differently by urdfdom"}}),
    [](const ::testing::TestParamInfo<BadFile> & p) { return p.param.file.substr(0, p.param.file.find('.')); });

// Every file of the corpus is in the list above (a new bad file cannot be forgotten).
TEST(BadUrdfCorpus, EveryFileIsTested)
{
  int n = 0;
  for(const auto & e : fs::directory_iterator(RBDGEN_CLI_BAD_DIR)) n += e.path().extension() == ".urdf" ? 1 : 0;
  EXPECT_EQ(n, 41);
}

// ---------------------------------------------------------------------------------------------
// Cases made on the fly

// The neighbours of the corpus, fixed by one edit each, generate: the checks are not too eager
// (values at the 1e9 magnitude limit, an axis of norm 1e-6, elements rbdgen ignores).
TEST_F(CliTest, CorpusNeighboursGenerate)
{
  const std::string inertial =
      "<inertial><origin xyz=\"1e9 0 0\"/><mass value=\"1e9\"/><inertia ixx=\"1e9\" ixy=\"0\" ixz=\"0\" iyy=\"1e9\" "
      "iyz=\"0\" izz=\"1e9\"/></inertial>";
  const std::string text =
      "<?xml version=\"1.0\"?>\n<robot name=\"neighbours\">\n"
      "  <link name=\"base\"><visual><geometry><mesh filename=\"package://x/base.stl\"/></geometry></visual></link>\n"
      "  <link name=\"upper_arm\">" + inertial + "</link>\n"
      "  <joint name=\"shoulder\" type=\"revolute\"><parent link=\"base\"/><child link=\"upper_arm\"/>"
      "<origin xyz=\"-1e9 0 1e-300\" rpy=\"0 0 0\"/><axis xyz=\"0 0 1e-6\"/>"
      "<limit lower=\"-1e30\" upper=\"1e30\" effort=\"1e30\" velocity=\"1e30\"/></joint>\n"
      "  <transmission name=\"t\"><type>transmission_interface/SimpleTransmission</type></transmission>\n"
      "  <gazebo reference=\"upper_arm\"><material>Gazebo/Grey</material></gazebo>\n"
      "</robot>\n";
  const fs::path urdf = dir() / "neighbours.urdf";
  writeFile(urdf, text);
  const Result r = rbdgen({"generate", urdf.string(), "--out", "out", "--namespace", "robot"}, dir());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir() / "out" / "robot" / "dynamics.hpp"));
  // The header is finite: no inf/nan constant was folded into it.
  const std::string header = readFile(dir() / "out" / "robot" / "dynamics.hpp");
  EXPECT_FALSE(std::regex_search(header, std::regex("\\b(inf|nan|INF|NAN|NaN)\\b")));
}

TEST_F(CliTest, TruncatedFileFailsCleanly)
{
  const std::string text = readFile(robot("ur5e"));
  const std::size_t end = text.rfind("</robot>");
  ASSERT_NE(end, std::string::npos);
  for(const std::size_t cut : {text.size() / 10, text.size() / 2, 9 * text.size() / 10, end + 3, end})
  {
    const fs::path urdf = dir() / "truncated.urdf";
    writeFile(urdf, text.substr(0, cut));
    expectFailsCleanly(dir(), [&](const std::string & out) {
      return std::vector<std::string>{"generate", urdf.string(), "--out", out, "--namespace", "robot"};
    }, {"truncated.urdf", "malformed"});
  }
}

TEST_F(CliTest, EmptyOrNonUrdfFileFailsCleanly)
{
  for(const std::string & text : {std::string(""), std::string("<?xml version=\"1.0\"?>\n<sdf version=\"1.6\"/>\n"),
                                  std::string("robot: not xml at all\n")})
  {
    const fs::path urdf = dir() / "not_a_robot.urdf";
    writeFile(urdf, text);
    expectFailsCleanly(dir(), [&](const std::string & out) {
      return std::vector<std::string>{"generate", urdf.string(), "--out", out, "--namespace", "robot"};
    }, {"not_a_robot.urdf", "malformed"});
  }
}

TEST_F(CliTest, UnknownBaseLinkFailsCleanly)
{
  const std::string urdf = robot("ur5e").string();
  expectFailsCleanly(dir(), [&](const std::string & out) {
    return std::vector<std::string>{"generate", urdf, "--out", out, "--namespace", "robot", "--base-link", "no_such_link"};
  }, {"ur5e.urdf", "link 'no_such_link'", "base link"});
}

TEST_F(CliTest, InvalidNamespaceFailsCleanly)
{
  const std::string urdf = robot("ur5e").string();
  for(const std::string ns : {"1robot", "a::b", "has space", "ur5e-arm", "a__b", "_Upper", "trailing_", "int", "namespace"})
  {
    SCOPED_TRACE(ns);
    expectFailsCleanly(dir(), [&](const std::string & out) {
      return std::vector<std::string>{"generate", urdf, "--out", out, "--namespace", ns};
    }, {"ur5e.urdf", "--namespace '" + ns + "'"});
  }
}

// A robot without a degree of freedom (fixed base, every joint fixed): no dynamics to generate, a
// clear error (from a URDF and from a scene); the same URDF as a free body generates.
TEST_F(CliTest, NoMovingJointFailsCleanly)
{
  writeFile(dir() / "rig.urdf", R"(<robot name="rig">
  <link name="base"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="camera"><inertial><mass value="0.2"/><inertia ixx="1e-3" iyy="1e-3" izz="1e-3" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="mount" type="fixed"><parent link="base"/><child link="camera"/><origin xyz="0 0 0.1"/></joint>
</robot>
)");
  writeFile(dir() / "rig.xml", R"(<scene name="rig"><robot urdf="rig.urdf"/></scene>
)");
  const std::string urdf = (dir() / "rig.urdf").string(), scene = (dir() / "rig.xml").string();
  expectFailsCleanly(dir(), [&](const std::string & out) {
    return std::vector<std::string>{"generate", urdf, "--out", out};
  }, {"rig.urdf", "robot 'rig'", "no moving joint", "--floating-base"});
  expectFailsCleanly(dir(), [&](const std::string & out) {
    return std::vector<std::string>{"generate", "--scene", scene, "--out", out};
  }, {"rig.xml", "robot 'rig'", "no moving joint"});
  const Result r = rbdgen({"generate", urdf, "--floating-base", "--out", "free"}, dir());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir() / "free" / "rig" / "dynamics.hpp"));
}

TEST_F(CliTest, UnwritableOutputDirFailsCleanly)
{
  // A path under a regular file cannot be created, even by root.
  const fs::path blocker = dir() / "blocker";
  writeFile(blocker, "not a directory\n");
  const std::vector<std::string> before = listTree(dir());
  for(const std::string out : {"blocker/sub", "blocker"})
  {
    const Result r = rbdgen({"generate", robot("ur5e").string(), "--out", out}, dir());
    EXPECT_TRUE(isOneLineError(r)) << out;
    EXPECT_TRUE(mentionsAll(r.err, {"ur5e.urdf", "blocker"})) << out;
    EXPECT_EQ(listTree(dir()), before) << out;
    EXPECT_EQ(readFile(blocker), "not a directory\n");
  }
}

} // namespace
} // namespace clitest
