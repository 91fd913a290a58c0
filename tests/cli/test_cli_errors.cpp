// rbdgen on bad input: every failure exits non-zero with exactly one line on stderr naming the
// file, the element (where there is one) and the reason, and writes nothing: no file or directory
// appears, and a good dynamics.hpp generated earlier into the same place stays byte-identical.
#include <functional>

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
                      BadFile{"nan_origin.urdf", {"joint 'shoulder'", "origin", "not finite"}}),
    [](const ::testing::TestParamInfo<BadFile> & p) { return p.param.file.substr(0, p.param.file.find('.')); });

// Every file of the corpus is in the list above (a new bad file cannot be forgotten).
TEST(BadUrdfCorpus, EveryFileIsTested)
{
  int n = 0;
  for(const auto & e : fs::directory_iterator(RBDGEN_CLI_BAD_DIR)) n += e.path().extension() == ".urdf" ? 1 : 0;
  EXPECT_EQ(n, 13);
}

// ---------------------------------------------------------------------------------------------
// Cases made on the fly

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
