// The scene file format: every element read into Scene (values checked against the text), URDF
// <dynamics> defaults and overrides, the scene's robot (locked joints, per-dof effects), and the
// broken-scene corpus bad/*.xml: each error is one line "<file>:<line>: <element> ['<name>']: <reason>",
// the expected line, element and reason written in the first line of each file.
#include <filesystem>
#include <fstream>
#include <regex>

#include "SceneTestUtils.h"

using namespace scenetest;
using namespace rbd::scene;
namespace fs = std::filesystem;

TEST(SceneLoader, ReadsEveryElement)
{
  const Scene s = sceneFromText(R"(<scene name="all">
  <robot urdf="quadruped.urdf" base="floating" base_link="trunk"/>
  <gravity x="0.5" y="-1" z="-3.7"/>
  <velocity_terms enabled="false"/>
  <joints damping="none" friction="urdf" friction_velocity="0.02">
    <joint name="FL_hip_joint" damping="0.4" armature="0.01"/>
    <lock name="HR_calf_joint" position="1.1"/>
  </joints>
  <external_wrench body="trunk"/>
  <external_wrench body="FL_calf"/>
  <contacts stiffness="1e4" damping="50" mu="0.6" slip_velocity="0.002" ground_height="-0.1">
    <point name="fl" body="FL_foot"/>
    <point name="knee" body="FR_calf" xyz="0 0.01 -0.02"/>
  </contacts>
  <outputs> <pose body="FL_foot"/> <jacobian body="trunk"/> <com/> <momentum/> <energy/> </outputs>
  <simulation integrator="rk4" dt="0.002" duration="3.5">
    <initial joint="Root" q="1 0 0 0 0.1 0.2 0.3" alpha="0 0 1 0 0 0"/>
    <initial joint="FL_thigh_joint" q="-0.8"/>
    <controller type="pd" kp="50" kd="2"> <target joint="FL_calf_joint" position="1.6"/> </controller>
  </simulation>
</scene>)");
  EXPECT_EQ(s.name, "all");
  EXPECT_EQ(s.file, "test.xml");
  EXPECT_EQ(fs::path(s.urdf), fs::path(robotsDir()) / "quadruped.urdf");
  EXPECT_TRUE(s.floatingBase);
  EXPECT_EQ(s.baseLink, "trunk");
  ASSERT_TRUE(s.gravity.has_value());
  EXPECT_EQ(*s.gravity, Eigen::Vector3d(0.5, -1, -3.7));
  EXPECT_FALSE(s.velocityTerms);
  EXPECT_EQ(s.frictionVelocity, 0.02);
  EXPECT_EQ(s.joints.at("FL_hip_joint").damping, 0.4);
  EXPECT_EQ(s.joints.at("FL_hip_joint").friction, 0.2); // URDF <dynamics friction="0.2">
  EXPECT_EQ(s.joints.at("FL_hip_joint").armature, 0.01);
  EXPECT_EQ(s.joints.at("FR_thigh_joint").damping, 0.0); // damping="none"
  EXPECT_EQ(s.joints.count("HR_calf_joint"), 0u);        // locked: no effects
  EXPECT_EQ(s.joints.size(), 11u);
  EXPECT_EQ(s.locked.at("HR_calf_joint"), std::vector<double>{1.1});
  EXPECT_EQ(s.externalWrenches, (std::vector<std::string>{"trunk", "FL_calf"}));
  ASSERT_EQ(s.contacts.size(), 2u);
  EXPECT_EQ(s.contacts[1].name, "knee");
  EXPECT_EQ(s.contacts[1].body, "FR_calf");
  EXPECT_EQ(s.contacts[1].point, Eigen::Vector3d(0, 0.01, -0.02));
  EXPECT_EQ(s.contactModel.stiffness, 1e4);
  EXPECT_EQ(s.contactModel.damping, 50);
  EXPECT_EQ(s.contactModel.mu, 0.6);
  EXPECT_EQ(s.contactModel.slipVelocity, 0.002);
  EXPECT_EQ(s.contactModel.groundHeight, -0.1);
  EXPECT_EQ(s.outputs.poses, std::vector<std::string>{"FL_foot"});
  EXPECT_EQ(s.outputs.jacobians, std::vector<std::string>{"trunk"});
  EXPECT_TRUE(s.outputs.com && s.outputs.momentum && s.outputs.energy);
  EXPECT_EQ(s.integrator, Integrator::RK4);
  EXPECT_EQ(s.dt, 0.002);
  EXPECT_EQ(s.duration, 3.5);
  EXPECT_EQ(s.initialQ.at("Root"), (std::vector<double>{1, 0, 0, 0, 0.1, 0.2, 0.3}));
  EXPECT_EQ(s.initialAlpha.at("Root"), (std::vector<double>{0, 0, 1, 0, 0, 0}));
  EXPECT_EQ(s.initialQ.at("FL_thigh_joint"), std::vector<double>{-0.8});
  EXPECT_EQ(s.controller.type, Controller::Type::PdHold);
  EXPECT_EQ(s.controller.kp, 50);
  EXPECT_EQ(s.controller.kd, 2);
  EXPECT_EQ(s.controller.target.at("FL_calf_joint"), 1.6);

  // the scene's robot: 6 + 11 dof, effects per dof, bodies by name
  const SceneRobot r = loadSceneRobot(s);
  const auto & mb = r.robot.mb;
  EXPECT_EQ(mb.nrDof(), 17);
  EXPECT_FALSE(mb.hasJoint("HR_calf_joint") && mb.joint(mb.jointIndexByName("HR_calf_joint")).dof() > 0);
  const int hip = mb.jointPosInDof(mb.jointIndexByName("FL_hip_joint"));
  EXPECT_EQ(r.damping[hip], 0.4);
  EXPECT_EQ(r.friction[hip], 0.2);
  EXPECT_EQ(r.armature[hip], 0.01);
  EXPECT_EQ(r.damping.head<6>().norm() + r.friction.head<6>().norm(), 0.0); // the free base
  EXPECT_EQ(mb.body(r.contactBodies[1]).name(), "FR_calf");
  EXPECT_EQ(mb.body(r.wrenchBodies[0]).name(), "trunk");
  // the initial state: Root q and alpha, a joint q, zero elsewhere
  const SceneDynamics dyn(r, s);
  const auto st = initialState(dyn);
  EXPECT_EQ(st.q.head<7>(), (Eigen::Matrix<double, 7, 1>() << 1, 0, 0, 0, 0.1, 0.2, 0.3).finished());
  EXPECT_EQ(st.q[mb.jointPosInParam(mb.jointIndexByName("FL_thigh_joint"))], -0.8);
  EXPECT_EQ(st.alpha[2], 1.0);
  EXPECT_EQ(st.alpha.norm(), 1.0);
}

TEST(SceneLoader, DefaultsFromUrdf)
{
  const Scene s = sceneFromText(sceneXml("quadruped.urdf", "", "floating"));
  EXPECT_EQ(s.name, "t");
  ASSERT_TRUE(s.gravity.has_value());
  EXPECT_EQ(*s.gravity, Eigen::Vector3d(0, 0, -9.81));
  EXPECT_TRUE(s.velocityTerms);
  EXPECT_EQ(s.joints.size(), 12u);
  for(const auto & [name, fx] : s.joints)
  {
    EXPECT_EQ(fx.damping, 0.01) << name; // robots/quadruped.urdf <dynamics damping="0.01" friction="0.2">
    EXPECT_EQ(fx.friction, 0.2) << name;
    EXPECT_EQ(fx.armature, 0.0) << name;
  }
  EXPECT_EQ(s.integrator, Integrator::SemiImplicitEuler);
  EXPECT_EQ(s.controller.type, Controller::Type::ZeroTorque);
  const Scene none = sceneFromText(sceneXml("quadruped.urdf", "<gravity enabled=\"false\"/><joints damping=\"none\" friction=\"none\"/>"));
  EXPECT_FALSE(none.gravity.has_value());
  for(const auto & [name, fx] : none.joints) EXPECT_EQ(fx.damping + fx.friction, 0.0) << name;
}

TEST(SceneLoader, RelativeUrdfPathIsRelativeToTheSceneFile)
{
  const Scene s = loadScene(scenesDir() + "/pendulum_damped.xml");
  EXPECT_EQ(fs::canonical(s.urdf), fs::canonical(fs::path(robotsDir()) / "pendulum.urdf"));
  EXPECT_EQ(s.joints.at("joint1").damping, 0.5);
}

TEST(SceneLoader, BrokenSceneCorpus)
{
  std::vector<fs::path> files;
  for(const auto & e : fs::directory_iterator(RBDGEN_SCENE_BAD_DIR))
    if(e.path().extension() == ".xml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 20u);
  const std::regex expectRe(R"(<!-- expect: (\d+) \| (.*?) \| (.*) -->)");
  for(const fs::path & f : files)
  {
    std::ifstream in(f);
    std::string first;
    std::getline(in, first);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(first, m, expectRe)) << f << ": first line must state the expected error";
    const std::string prefix = f.string() + ":" + m[1].str() + ": " + m[2].str() + ": ";
    try
    {
      loadScene(f.string());
      ADD_FAILURE() << f << ": loaded without error";
    }
    catch(const SceneError & e)
    {
      const std::string msg = e.what();
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      EXPECT_EQ(msg.rfind(prefix, 0), 0u) << "message: " << msg << "\nexpected prefix: " << prefix;
      EXPECT_NE(msg.find(m[3].str(), prefix.size()), std::string::npos) << "message: " << msg << "\nexpected reason: " << m[3];
    }
  }
}

TEST(SceneLoader, MissingSceneFile)
{
  try
  {
    loadScene("/nonexistent/scene.xml");
    FAIL();
  }
  catch(const SceneError & e)
  {
    EXPECT_STREQ(e.what(), "/nonexistent/scene.xml: file: cannot be read");
  }
}
