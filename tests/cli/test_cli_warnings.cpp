// rbdgen generate / info and the model's warnings (issue 17, items 2, 3, 5): the loader's warnings
// on stderr as "rbdgen: warning: ...", exit 0 unless --strict; a URDF floating joint used as the
// floating base; stacked free joints; near-massless links; the robots we ship and the shared
// ones give no inertia warning. URDFs are written here; expected values come from their text.
#include <regex>

#include "CliRun.h"

namespace clitest
{
namespace
{

std::string link(const std::string & name, double m, const std::string & com = "0 0 0", double inertia = -1)
{
  const double I = inertia < 0 ? 0.1 * m : inertia;
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "<link name=\"%s\"><inertial><origin xyz=\"%s\"/><mass value=\"%.17g\"/><inertia ixx=\"%.17g\" "
                "iyy=\"%.17g\" izz=\"%.17g\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n",
                name.c_str(), com.c_str(), m, I, I, I);
  return buf;
}

std::string joint(const std::string & name, const std::string & type, const std::string & parent, const std::string & child,
                  const std::string & more = "")
{
  return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent + "\"/><child link=\"" + child +
         "\"/><origin xyz=\"0.2 0 0\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" "
         "velocity=\"1\"/>" + more + "</joint>\n";
}

/// massless world --floating_base--> base --elbow--> arm (+ extra)
std::string floatingUrdf(const std::string & extra = "")
{
  return "<robot name=\"fb\"><link name=\"world\"/>\n" + link("base", 2) + link("arm", 1, "0.3 0 0") +
         joint("floating_base", "floating", "world", "base") + joint("elbow", "revolute", "base", "arm") + extra + "</robot>";
}

std::vector<std::string> stderrLines(const std::string & err)
{
  std::vector<std::string> v;
  std::size_t b = 0;
  for(std::size_t e; (e = err.find('\n', b)) != std::string::npos; b = e + 1) v.push_back(err.substr(b, e - b));
  return v;
}

/// Every stderr line is a warning; one of them contains all of `words`.
::testing::AssertionResult warns(const Result & r, const std::vector<std::string> & words)
{
  bool found = false;
  for(const auto & l : stderrLines(r.err))
  {
    if(l.rfind("rbdgen: warning: ", 0) != 0) return ::testing::AssertionFailure() << "not a warning line: " << l;
    bool all = true;
    for(const auto & w : words) all = all && l.find(w) != std::string::npos;
    found = found || all;
  }
  if(!found) return ::testing::AssertionFailure() << "no warning with the expected words in: " << r.err;
  return ::testing::AssertionSuccess();
}

int headerInt(const std::string & header, const std::string & name)
{
  std::smatch m;
  if(!std::regex_search(header, m, std::regex("constexpr int " + name + " = ([0-9]+);"))) return -1;
  return std::stoi(m[1]);
}

TEST_F(CliTest, GenerateShowsTheLoadersWarningsAndSucceeds)
{
  // A mimic revolute joint (coupled: not a dof, no warning), a mimic fixed joint (nothing to couple:
  // no warning) and a mimic of that fixed joint (kept as an independent joint: the warning says so).
  const std::string urdf = "<robot name=\"mim\">" + link("base", 1) + link("a", 1, "0.1 0 0") + link("b", 1, "0.1 0 0") +
                           link("c", 1, "0.1 0 0") + link("d", 1, "0.1 0 0") + joint("lead", "revolute", "base", "a") +
                           joint("follower", "revolute", "a", "b", "<mimic joint=\"lead\" multiplier=\"2\"/>") +
                           joint("stuck", "fixed", "b", "c", "<mimic joint=\"lead\"/>") +
                           joint("orphan", "revolute", "c", "d", "<mimic joint=\"stuck\"/>") + "</robot>";
  writeFile(dir() / "mim.urdf", urdf);
  const Result r = rbdgen({"generate", "mim.urdf", "--out", "out"}, dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(warns(r, {"mim.urdf: joint 'orphan'", "mimics joint 'stuck'", "fixed", "independent joint"}));
  EXPECT_EQ(r.err.find("'follower'"), std::string::npos) << r.err;
  EXPECT_EQ(stderrLines(r.err).size(), 1u) << r.err;
  const std::string header = readFile(dir() / "out/mim/dynamics.hpp");
  EXPECT_EQ(headerInt(header, "nv"), 3); // the full model, NS::independent, first
  EXPECT_NE(header.find("constexpr int nv = 2;"), std::string::npos); // the API: lead and orphan; follower = 2 lead
  EXPECT_NE(header.find("\"follower = 2 * lead + 0\""), std::string::npos);
  // Warnings do not fail --strict either: they are not mass matrix hazards.
  EXPECT_EQ(rbdgen({"generate", "mim.urdf", "--out", "out", "--strict"}, dir()).code, 0);
  // --independent-mimic: the old behaviour, with a warning per mimic joint and the option in the provenance.
  const Result ind = rbdgen({"generate", "mim.urdf", "--out", "ind", "--independent-mimic"}, dir());
  ASSERT_EQ(ind.code, 0) << ind.err;
  EXPECT_TRUE(warns(ind, {"mim.urdf", "not coupled (--independent-mimic)", "follower = 2 * lead + 0"}));
  const std::string indHeader = readFile(dir() / "ind/mim/dynamics.hpp");
  EXPECT_EQ(headerInt(indHeader, "nv"), 3);
  EXPECT_NE(indHeader.find("independent mimic joints"), std::string::npos);
  // A scene of the same robot couples them too (its full model in NS::independent), or not with
  // --independent-mimic.
  writeFile(dir() / "mim.xml", "<scene name=\"mims\"><robot urdf=\"mim.urdf\"/><gravity/>"
                               "<joints><joint name=\"follower\" damping=\"0.1\"/></joints></scene>");
  const Result sc = rbdgen({"generate", "--scene", "mim.xml", "--out", "sc"}, dir());
  ASSERT_EQ(sc.code, 0) << sc.err;
  EXPECT_TRUE(warns(sc, {"joint 'orphan'", "mimics joint 'stuck'"}));
  EXPECT_EQ(stderrLines(sc.err).size(), 1u) << sc.err;
  const std::string scHeader = readFile(dir() / "sc/mims/dynamics.hpp");
  EXPECT_NE(scHeader.find("namespace mims::independent"), std::string::npos);
  EXPECT_EQ(headerInt(scHeader, "nv"), 3); // the full model first
  EXPECT_NE(scHeader.find("constexpr int nv = 2;"), std::string::npos);
  EXPECT_NE(scHeader.find("\"follower = 2 * lead + 0\""), std::string::npos);
  const Result scInd = rbdgen({"generate", "--scene", "mim.xml", "--out", "scind", "--independent-mimic"}, dir());
  ASSERT_EQ(scInd.code, 0) << scInd.err;
  EXPECT_TRUE(warns(scInd, {"mim.xml", "not coupled (--independent-mimic)", "follower = 2 * lead + 0"}));
  const std::string scIndHeader = readFile(dir() / "scind/mims/dynamics.hpp");
  EXPECT_EQ(scIndHeader.find("mims::independent"), std::string::npos);
  EXPECT_EQ(scIndHeader.find("constexpr int nv = 2;"), std::string::npos);
  EXPECT_NE(scIndHeader.find("independent mimic joints"), std::string::npos);
}

TEST_F(CliTest, MimicCycleIsAnError)
{
  const std::string urdf = "<robot name=\"cyc\">" + link("base", 1) + link("a", 1, "0.1 0 0") + link("b", 1, "0.1 0 0") +
                           joint("j1", "revolute", "base", "a", "<mimic joint=\"j2\"/>") +
                           joint("j2", "revolute", "a", "b", "<mimic joint=\"j1\"/>") + "</robot>";
  writeFile(dir() / "cyc.urdf", urdf);
  const Result r = rbdgen({"generate", "cyc.urdf", "--out", "out"}, dir());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("cyc.urdf: joint 'j1': mimic cycle j1 -> j2 -> j1"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir() / "out"));
}

TEST_F(CliTest, FloatingJointUnderAMasslessRootIsTheFloatingBase)
{
  writeFile(dir() / "fb.urdf", floatingUrdf());
  const Result r = rbdgen({"generate", "fb.urdf", "--out", "out", "--floating-base", "--strict"}, dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(warns(r, {"fb.urdf: joint 'floating_base'", "link 'world'", "floating base"}));
  const std::string header = readFile(dir() / "out/fb/dynamics.hpp");
  EXPECT_EQ(headerInt(header, "nv"), 6 + 1); // one free joint and the revolute
  EXPECT_EQ(headerInt(header, "nq"), 7 + 1);
  EXPECT_NE(header.find("has_forward_dynamics = true;"), std::string::npos);
}

TEST_F(CliTest, StackedFreeJointsWarnOrFailWithStrict)
{
  // world has a second, massless child: two free joints stay stacked and H is singular.
  writeFile(dir() / "fb.urdf",
            floatingUrdf("<link name=\"marker\"/><joint name=\"mark\" type=\"fixed\"><parent link=\"world\"/><child "
                         "link=\"marker\"/></joint>"));
  const Result strict = rbdgen({"generate", "fb.urdf", "--out", "out", "--floating-base", "--strict"}, dir());
  EXPECT_TRUE(isOneLineError(strict));
  EXPECT_NE(strict.err.find("'Root'"), std::string::npos) << strict.err;
  EXPECT_NE(strict.err.find("'floating_base'"), std::string::npos) << strict.err;
  EXPECT_FALSE(fs::exists(dir() / "out"));
  const Result r = rbdgen({"generate", "fb.urdf", "--out", "out", "--floating-base"}, dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(warns(r, {"free joint 'Root'", "joint 'floating_base'", "singular"}));
  const std::string header = readFile(dir() / "out/fb/dynamics.hpp");
  EXPECT_EQ(headerInt(header, "nv"), 6 + 6 + 1);
  EXPECT_NE(header.find("has_forward_dynamics = false;"), std::string::npos);
}

TEST_F(CliTest, NearMasslessLinkWarnsOrFailsWithStrict)
{
  // base -> l1 (1 kg) -> tip (m kg, COM on the axis, I = m 1e-6): S^T Ic S = m 1e-6 kg m^2 against
  // M L^2 ~ 2 kg x (0.4 m)^2: a negligible ratio for 1e-6 kg and 1e-12 kg, not for 0.1 kg.
  for(const double m : {1e-1, 1e-6, 1e-12})
  {
    const std::string urdf = "<robot name=\"tiny\">" + link("base", 1) + link("l1", 1, "0.1 0 0") +
                             link("tip", m, "0 0 0", 1e-6 * m) + joint("j1", "revolute", "base", "l1") +
                             joint("j2", "revolute", "l1", "tip") + "</robot>";
    writeFile(dir() / "tiny.urdf", urdf);
    fs::remove_all(dir() / "out2");
    const Result r = rbdgen({"generate", "tiny.urdf", "--out", "out"}, dir());
    ASSERT_EQ(r.code, 0) << r.err;
    const Result s = rbdgen({"generate", "tiny.urdf", "--out", "out2", "--strict"}, dir());
    if(m > 1e-3)
    {
      EXPECT_EQ(r.err, "");
      EXPECT_EQ(s.code, 0) << s.err;
      continue;
    }
    EXPECT_TRUE(warns(r, {"tiny.urdf: joint 'j2': negligible effective inertia", "ill-conditioned"})) << m;
    EXPECT_EQ(r.err.find("'j1'"), std::string::npos) << r.err;
    EXPECT_TRUE(isOneLineError(s)) << m;
    EXPECT_NE(s.err.find("joint 'j2'"), std::string::npos) << s.err;
    EXPECT_FALSE(fs::exists(dir() / "out2"));
    // info shows the same warning.
    const Result i = rbdgen({"info", "tiny.urdf"}, dir());
    EXPECT_NE(i.out.find("warning: tiny.urdf: joint 'j2': negligible effective inertia"), std::string::npos) << i.out;
  }
}

TEST_F(CliTest, RealRobotsHaveNoNegligibleInertia)
{
  std::vector<fs::path> urdfs;
  for(const fs::path & d : {fs::path(RBDGEN_SOURCE_DIR) / "robots", fs::path(RBDGEN_SHARED_ROBOTS_DIR)})
    if(fs::exists(d))
      for(const auto & e : fs::directory_iterator(d))
        if(e.path().extension() == ".urdf") urdfs.push_back(e.path());
  ASSERT_GE(urdfs.size(), 8u);
  for(const auto & u : urdfs)
    for(const bool floating : {false, true})
    {
      const Result r = floating ? rbdgen({"info", u.string(), "--floating-base"}, dir()) : rbdgen({"info", u.string()}, dir());
      ASSERT_EQ(r.code, 0) << u << r.err;
      EXPECT_EQ(r.out.find("negligible effective inertia"), std::string::npos) << u << (floating ? " floating" : "") << "\n"
                                                                               << r.out;
      const auto b = r.out.find("mass matrix at q = 0:");
      ASSERT_NE(b, std::string::npos) << r.out;
      if(!floating) std::printf("  %-22s %s", u.filename().c_str(), r.out.substr(b, r.out.find('\n', b) - b + 1).c_str());
    }
}

} // namespace
} // namespace clitest
