// Generator side of scenes, without compiling headers:
//  - a disabled effect leaves no trace: starting from a scene with every effect off, adding one
//    effect adds its names to the header and adds emitted operations; the bare header names none;
//  - the massless-subtree policy (issue 5): no forward dynamics, a comment naming the joint, a
//    warning (an error with --strict); armature > 0 on the joint restores forward dynamics;
//  - the command line with --scene: provenance (scene sha256 by coreutils), depfile, errors on one
//    line with nothing written.
#include <cctype>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include <rbd/scene/SceneLoader.h>

#include "../cli/CliRun.h"
#include "Generate.h"
#include "emit/SceneHeader.h"

namespace
{
namespace sc = rbd::scene;
using clitest::isOneLineError;
using clitest::rbdgen;
namespace fs = std::filesystem;

std::string scenePath(const std::string & name)
{
  return std::string(SG_SCENES_DIR) + "/" + name + ".xml";
}

std::string header(const sc::Scene & scene)
{
  const sc::SceneRobot sr = sc::loadSceneRobot(scene);
  const rbdgen::RobotModel rm = rbdgen::robotModelFromUrdf(sr.robot);
  return rbdgen::emit::emitDynamicsHeader(rm, rbdgen::emit::sceneHeaderSpec(rm, scene, sr, "ns", "// provenance"));
}

std::string lower(std::string s)
{
  for(char & c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool has(const std::string & text, const std::string & word)
{
  return lower(text).find(lower(word)) != std::string::npos;
}

/// Floating-point operations written in the header: binary + - * / and std:: calls.
long operations(const std::string & text)
{
  long n = 0;
  for(const char * op : {" * ", " + ", " - ", " / ", "std::sqrt", "std::sin", "std::cos"})
    for(std::size_t p = text.find(op); p != std::string::npos; p = text.find(op, p + 1)) ++n;
  return n;
}

struct Effect
{
  const char * name;
  std::function<void(sc::Scene &)> enable;
  std::vector<const char *> markers; ///< words only this effect writes
};

std::vector<Effect> effects()
{
  return {
      {"gravity", [](sc::Scene & s) { s.gravity = Eigen::Vector3d(0, 0, -9.81); }, {"gravity"}},
      {"velocity terms", [](sc::Scene & s) { s.velocityTerms = true; }, {"velocity_torques", "coriolis", "centrifugal"}},
      {"damping", [](sc::Scene & s) { s.joints["FL_hip_joint"].damping = 0.5; }, {"damping"}},
      {"friction", [](sc::Scene & s) { s.joints["FL_thigh_joint"].friction = 0.3; }, {"friction"}},
      {"armature", [](sc::Scene & s) { s.joints["FL_calf_joint"].armature = 0.01; }, {"armature"}},
      {"external wrench", [](sc::Scene & s) { s.externalWrenches = {"trunk"}; }, {"wrench"}},
      {"contacts",
       [](sc::Scene & s) {
         s.contacts = {sc::ContactPoint{"FL", "FL_foot", Eigen::Vector3d::Zero()}};
         s.contactModel.stiffness = 1e4;
         s.contactModel.damping = 100;
         s.contactModel.mu = 0.7;
       },
       {"contact"}},
      {"pose output", [](sc::Scene & s) { s.outputs.poses = {"FL_foot"}; }, {"pose_"}},
      {"jacobian output", [](sc::Scene & s) { s.outputs.jacobians = {"FL_foot"}; }, {"jacobian_"}},
      {"com output", [](sc::Scene & s) { s.outputs.com = true; }, {"center_of_mass"}},
      {"momentum output", [](sc::Scene & s) { s.outputs.momentum = true; }, {"momentum"}},
      {"energy output", [](sc::Scene & s) { s.outputs.energy = true; }, {"energy"}},
      {"rk4", [](sc::Scene & s) { s.integrator = sc::Integrator::RK4; }, {"configuration_derivative", "runge"}},
      {"explicit euler", [](sc::Scene & s) { s.integrator = sc::Integrator::ExplicitEuler; }, {"explicit"}},
  };
}

TEST(SceneEmit, DisabledEffectLeavesNoTrace)
{
  const sc::Scene bare = sc::loadScene(scenePath("quadruped_bare"));
  const std::string bareText = header(bare);
  const long bareOps = operations(bareText);
  for(const Effect & e : effects())
    for(const char * m : e.markers)
    {
      EXPECT_FALSE(has(bareText, m)) << "bare header names '" << m << "' (" << e.name << ")";
    }
  EXPECT_FALSE(has(bareText, "generalized_bias")) << "nothing to add to tau: no bias function";
  for(const Effect & e : effects())
  {
    sc::Scene s = bare;
    e.enable(s);
    const std::string text = header(s);
    for(const char * m : e.markers) EXPECT_TRUE(has(text, m)) << e.name << ": '" << m << "' missing";
    for(const Effect & other : effects())
    {
      if(other.name == e.name) continue;
      for(const char * m : other.markers)
      {
        EXPECT_FALSE(has(text, m)) << e.name << " brings in '" << m << "' of " << other.name;
      }
    }
    const long ops = operations(text);
    std::printf("[ %-16s ] emitted operations %ld (bare %ld)\n", e.name, ops, bareOps);
    const bool outputOrIntegrator = has(e.name, "output") || e.name == std::string("rk4") || e.name == std::string("explicit euler");
    if(!outputOrIntegrator)
    {
      EXPECT_GT(ops, bareOps) << e.name;
    }
  }
}

TEST(SceneEmit, EffectsAppearOnlyWhereTheyAct)
{
  // Velocity terms off: no cross products of velocities in the dynamics (v x S alpha, v x* I v),
  // the bias with gravity only equals gravity_torques' operations.
  sc::Scene s = sc::loadScene(scenePath("arm_gravity"));
  const std::string text = header(s);
  EXPECT_TRUE(has(text, "gravity_torques"));
  EXPECT_FALSE(has(text, "vxvJ")) << "a velocity product in a scene without velocity terms";
  EXPECT_FALSE(has(text, "vxIv"));
  s.velocityTerms = true;
  EXPECT_TRUE(has(header(s), "vxIv"));
}

TEST(SceneEmit, MasslessSubtreePolicy)
{
  const std::string singular = header(sc::loadScene(scenePath("massless")));
  EXPECT_TRUE(has(singular, "has_forward_dynamics = false"));
  EXPECT_FALSE(has(singular, "forward_dynamics(")) << "forward dynamics emitted for a singular mass matrix";
  EXPECT_FALSE(has(singular, " step("));
  EXPECT_TRUE(has(singular, "'tip_joint'")) << "the comment names the joint";
  const std::string fixed = header(sc::loadScene(scenePath("massless_armature")));
  EXPECT_TRUE(has(fixed, "has_forward_dynamics = true"));
  EXPECT_TRUE(has(fixed, "forward_dynamics("));
  EXPECT_TRUE(has(fixed, " step("));
}

class SceneCli : public clitest::CliTest
{
};

TEST_F(SceneCli, PlainHeaderMasslessWarningAndStrict)
{
  const std::string urdf = std::string(SG_SCENES_DIR) + "/massless_tip.urdf";
  const auto r = rbdgen({"generate", urdf, "--out", "out"}, dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.err, "warning") && has(r.err, "'tip_joint'")) << r.err;
  const std::string text = clitest::readFile(dir() / "out/massless_tip/dynamics.hpp");
  EXPECT_TRUE(has(text, "has_forward_dynamics = false"));
  EXPECT_FALSE(has(text, "forward_dynamics("));
  EXPECT_TRUE(has(text, "inverse_dynamics(")) << "the rest of the API stays";
  const auto strict = rbdgen({"generate", urdf, "--out", "strict", "--strict"}, dir());
  EXPECT_TRUE(isOneLineError(strict));
  EXPECT_TRUE(has(strict.err, "'tip_joint'")) << strict.err;
  EXPECT_FALSE(fs::exists(dir() / "strict"));
}

TEST_F(SceneCli, GenerateWithSceneProvenanceAndDepfile)
{
  const std::string scene = scenePath("pendulum_damped");
  const auto r = rbdgen({"generate", "--scene", scene, "--out", "out", "--depfile", "dyn.d"}, dir());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = clitest::readFile(dir() / "out/pendulum_damped/dynamics.hpp");
  EXPECT_TRUE(has(text, "// Scene: pendulum_damped.xml (sha256 " + clitest::sha256sum(scene) + ")")) << text.substr(0, 600);
  EXPECT_TRUE(has(text, "// Effects: gravity (0, -4, -9)")) << text.substr(0, 600);
  const std::string dep = clitest::readFile(dir() / "dyn.d");
  EXPECT_TRUE(has(dep, "pendulum_damped.xml") && has(dep, "double_pendulum.urdf")) << dep;
  // deterministic: the same scene gives the same bytes
  const auto again = rbdgen({"generate", "--scene", scene, "--out", "again"}, dir());
  ASSERT_EQ(again.code, 0);
  EXPECT_EQ(text, clitest::readFile(dir() / "again/pendulum_damped/dynamics.hpp"));
}

TEST_F(SceneCli, BadSceneOneLineErrorNothingWritten)
{
  clitest::writeFile(dir() / "bad.xml", "<scene name=\"bad\">\n  <robot urdf=\"" + robot("pendulum").string() +
                                            "\"/>\n  <gravity x=\"0\" y=\"0\" z=\"-9.81\" w=\"1\"/>\n</scene>\n");
  const auto r = rbdgen({"generate", "--scene", "bad.xml", "--out", "out"}, dir());
  EXPECT_TRUE(isOneLineError(r));
  EXPECT_TRUE(has(r.err, "bad.xml:3")) << r.err;
  EXPECT_FALSE(fs::exists(dir() / "out"));
  clitest::writeFile(dir() / "unknown_link.xml", "<scene>\n  <robot urdf=\"" + robot("pendulum").string() +
                                                     "\"/>\n  <external_wrench body=\"nope\"/>\n</scene>\n");
  const auto r2 = rbdgen({"generate", "--scene", "unknown_link.xml", "--out", "out"}, dir());
  EXPECT_TRUE(isOneLineError(r2));
  EXPECT_TRUE(has(r2.err, "nope")) << r2.err;
  EXPECT_FALSE(fs::exists(dir() / "out"));
  const auto both = rbdgen({"generate", robot("pendulum").string(), "--scene", scenePath("arm_gravity"), "--out", "out"}, dir());
  EXPECT_TRUE(isOneLineError(both));
  EXPECT_FALSE(fs::exists(dir() / "out"));
  const auto none = rbdgen({"generate", "--out", "out"}, dir());
  EXPECT_TRUE(isOneLineError(none));
}

} // namespace
