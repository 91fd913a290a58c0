// Every URDF of the project (robots/) and of /work/shared/robots loads with a fixed and a floating
// base, with the body and dof counts read off the files by hand (robots/*.urdf, and the table of
// /work/shared/robots/SOURCES.md).
#include <filesystem>
#include <map>

#include <gtest/gtest.h>

#include <rbd/parsers/MimicCoupling.h>

#include "LoaderTestUtil.h"
#include "TestModels.h"

namespace fs = std::filesystem;
using rbd::parsers::fromUrdfFile;
using rbd::parsers::ParserOptions;

namespace
{

struct Expected
{
  int bodies; ///< <link> elements
  int dof;    ///< revolute/continuous/prismatic 1, planar 3, floating 6 (fixed base)
  int params; ///< floating counts 7
};

// Counted in the files (grep '<link name=' and the joint types).
const std::map<std::string, Expected> projectRobots{
    {"ur5e", {8, 6, 6}},         {"panda_arm", {11, 7, 7}},  {"quadruped", {17, 12, 12}},
    {"humanoid", {34, 29, 29}},  {"pendulum", {2, 1, 1}},    {"double_pendulum", {4, 2, 2}},
    {"iiwa7", {9, 7, 7}},
    // 5 revolute + 1 continuous + 2 prismatic + 2 planar (3) + 1 floating (6 dof, 7 params)
    {"all_joints", {16, 20, 21}},
};

// From /work/shared/robots/SOURCES.md (links, DoF columns).
const std::map<std::string, Expected> sharedRobots{
    {"ur5", {11, 6, 6}},           {"panda", {13, 9, 9}},          {"kinova", {13, 6, 6}},
    {"solo12", {17, 12, 12}},      {"anymal", {23, 12, 12}},       {"hyq", {19, 12, 12}},
    {"talos_reduced", {60, 32, 32}}, {"talos_full_v2", {60, 44, 44}}, {"romeo", {82, 55, 55}},
    {"icub_reduced", {56, 29, 29}}, {"baxter", {57, 19, 19}},       {"double_pendulum", {3, 2, 2}},
};

std::vector<fs::path> urdfFiles(const fs::path & dir)
{
  std::vector<fs::path> out;
  for(const auto & e : fs::directory_iterator(dir))
    if(e.path().extension() == ".urdf") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

/// Load fixed and floating; check counts (when known), finite FK and the root placement.
void checkRobot(const fs::path & file, const std::map<std::string, Expected> & table)
{
  SCOPED_TRACE(file.string());
  ParserOptions fixedOpt, floatOpt;
  floatOpt.fixed = false;
  const auto fixedR = fromUrdfFile(file.string(), fixedOpt);
  const auto floatR = fromUrdfFile(file.string(), floatOpt);
  const rbd::MultiBody & mb = fixedR.mb;

  EXPECT_EQ(mb.joint(0).type(), rbd::Joint::Fixed);
  EXPECT_EQ(floatR.mb.joint(0).type(), rbd::Joint::Free);
  EXPECT_EQ(floatR.mb.joint(0).name(), "Root");
  // all_joints.urdf has its own floating joint under a massless `world` link: with a floating
  // base, that joint is the base (world and the joint dropped), not a second free joint.
  const bool ownFloating = file.stem() == "all_joints";
  EXPECT_EQ(floatR.mb.nrDof(), mb.nrDof() + (ownFloating ? 0 : 6));
  EXPECT_EQ(floatR.mb.nrParams(), mb.nrParams() + (ownFloating ? 0 : 7));
  EXPECT_EQ(floatR.mb.nrBodies(), mb.nrBodies() - (ownFloating ? 1 : 0));
  EXPECT_EQ(static_cast<int>(fixedR.mbg.nrNodes()), mb.nrBodies());
  auto it = table.find(file.stem().string());
  if(it != table.end())
  {
    EXPECT_EQ(mb.nrBodies(), it->second.bodies);
    EXPECT_EQ(mb.nrDof(), it->second.dof);
    EXPECT_EQ(mb.nrParams(), it->second.params);
  }
  // Zero configuration, base link at the world origin, finite poses; parents before children.
  EXPECT_MAT_NEAR(fixedR.mbc.bodyPosW[0].matrix(), sva::PTransformd::Identity().matrix(), 0.0);
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    EXPECT_LT(mb.parent(i), i);
    EXPECT_TRUE(fixedR.mbc.bodyPosW[static_cast<std::size_t>(i)].matrix().allFinite()) << mb.body(i).name();
    EXPECT_GE(mb.body(i).inertia().mass(), 0.0);
  }
  std::vector<std::vector<double>> zero;
  for(const auto & j : mb.joints()) zero.push_back(j.zeroParam());
  EXPECT_EQ(fixedR.mbc.q, zero);
  // Every non-Fixed URDF joint has limits of the joint's sizes.
  for(const auto & j : mb.joints())
  {
    if(j.type() == rbd::Joint::Fixed) continue;
    ASSERT_TRUE(fixedR.limits.lower.count(j.name())) << j.name();
    EXPECT_EQ(static_cast<int>(fixedR.limits.lower.at(j.name()).size()), j.params());
    EXPECT_EQ(static_cast<int>(fixedR.limits.torque.at(j.name()).size()), j.dof());
  }
}

} // namespace

TEST(LoaderRobots, ProjectRobotsLoadFixedAndFloating)
{
  const fs::path dir = fs::path(RBDGEN_SOURCE_DIR) / "robots";
  const auto files = urdfFiles(dir);
  ASSERT_FALSE(files.empty()) << "no URDF in " << dir;
  int known = 0;
  for(const auto & f : files)
  {
    checkRobot(f, projectRobots);
    known += static_cast<int>(projectRobots.count(f.stem().string()));
  }
  EXPECT_GE(known, 3) << "expected the project robots ur5e, panda_arm, quadruped... in " << dir;
}

TEST(LoaderRobots, SharedThirdPartyRobotsLoadFixedAndFloating)
{
  const fs::path dir = RBDGEN_SHARED_ROBOTS_DIR;
  if(!fs::is_directory(dir)) GTEST_SKIP() << "missing directory " << dir;
  const auto files = urdfFiles(dir);
  ASSERT_FALSE(files.empty());
  for(const auto & f : files)
  {
    checkRobot(f, sharedRobots);
    EXPECT_TRUE(sharedRobots.count(f.stem().string())) << "unknown robot " << f;
  }
}

TEST(LoaderRobots, SharedRobotsMimicAndDampingKept)
{
  const fs::path dir = RBDGEN_SHARED_ROBOTS_DIR;
  if(!fs::is_directory(dir)) GTEST_SKIP() << "missing directory " << dir;
  // SOURCES.md: panda has 1 mimic joint (panda_finger_joint2) and 9 joints with damping.
  const auto panda = fromUrdfFile((dir / "panda.urdf").string());
  ASSERT_EQ(panda.mimics.size(), 1u);
  EXPECT_EQ(panda.mimics.begin()->first, "panda_finger_joint2");
  EXPECT_EQ(panda.mimics.begin()->second.joint, "panda_finger_joint1");
  int damped = 0;
  for(const auto & [name, d] : panda.dynamics) damped += d.damping != 0;
  EXPECT_EQ(damped, 9);
  for(const auto & w : panda.warnings) EXPECT_EQ(w.find("panda_finger_joint2"), std::string::npos) << w;
  // Coupled: the finger follows the other one (multiplier 1, offset 0), one dof less.
  std::vector<std::string> warnings;
  const auto c = rbd::parsers::coupleMimics(panda, "panda.urdf", &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(c.nv, panda.mb.nrDof() - 1);
  ASSERT_EQ(c.coupled.size(), 1u);
  EXPECT_EQ(c.coupled[0], "panda_finger_joint2 = 1 * panda_finger_joint1 + 0");
}
