// Physics along simulated trajectories (runtime scene, every integrator): energy conservation with
// stated drift bounds, RK4's 4th-order convergence, dissipation equal to the damping work, the damped
// pendulum against the closed-form damped oscillator, momentum conservation in zero gravity, a box
// and the quadruped settling on compliant contacts (statics: sum of normal forces = m g), and every
// shipped scene loading and simulating.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <rbd/scene/Controller.h>

#include "SceneTestUtils.h"

using namespace scenetest;
using namespace rbd::scene;
namespace fs = std::filesystem;

namespace
{

/// Simulate `steps` steps; after each step call f(step index k >= 1, state).
template<class F>
void simulate(const SceneDynamics & dyn, SceneState<double> & s, long steps, double dt, Integrator integ, F && f)
{
  const SceneController ctrl(dyn, s);
  for(long k = 1; k <= steps; ++k)
  {
    step(dyn, s, ctrl.torque(s.q, s.alpha), dt, integ);
    f(k, s);
  }
}

double totalEnergy(const SceneDynamics & dyn, const SceneState<double> & s)
{
  return dyn.kineticEnergy(s.q, s.alpha) + dyn.potentialEnergy(s.q) + dyn.contactEnergy(s.q);
}

const char * integratorName(Integrator i)
{
  return i == Integrator::RK4 ? "rk4" : i == Integrator::ExplicitEuler ? "explicit_euler" : "semi_implicit_euler";
}

/// Max |E(t) - E(0)| over 2 s of the undamped double pendulum released at (1.0, -0.5) rad.
double doublePendulumDrift(Integrator integ, double dt)
{
  Model<double> m(sceneFromText(sceneXml("double_pendulum.urdf", R"(<joints damping="none" friction="none"/>
    <simulation><initial joint="joint1" q="1.0"/><initial joint="joint2" q="-0.5"/></simulation>)")));
  SceneState<double> s = initialState(m.dyn);
  const double E0 = totalEnergy(m.dyn, s);
  double drift = 0;
  simulate(m.dyn, s, std::lround(2.0 / dt), dt, integ,
           [&](long, const SceneState<double> & st) { drift = std::max(drift, std::abs(totalEnergy(m.dyn, st) - E0)); });
  return drift;
}

} // namespace

// Energy scale: m g l ~ 1.7 * 9.81 * 1 = 17 J. Stated bounds (2 s, double pendulum from rest at
// (1, -0.5) rad): RK4 dt = 1e-3: 1e-7 J; semi-implicit Euler dt = 1e-3: 0.05 J (bounded oscillation,
// symplectic); explicit Euler dt = 1e-4: 0.1 J (drifts upward).
TEST(ScenePhysics, EnergyConservedWithoutDampingOrContacts)
{
  struct Case
  {
    Integrator integ;
    double dt, bound;
  };
  for(const Case & c : {Case{Integrator::RK4, 1e-3, 1e-7}, Case{Integrator::SemiImplicitEuler, 1e-3, 0.05},
                        Case{Integrator::ExplicitEuler, 1e-4, 0.1}})
  {
    const double drift = doublePendulumDrift(c.integ, c.dt);
    std::cout << "[ measured ] double pendulum, 2 s, " << integratorName(c.integ) << " dt " << c.dt
              << ": max |E - E0| = " << drift << " J (bound " << c.bound << ")\n";
    EXPECT_LT(drift, c.bound) << integratorName(c.integ);
  }
}

TEST(ScenePhysics, Rk4IsFourthOrder)
{
  const double coarse = doublePendulumDrift(Integrator::RK4, 4e-3), fine = doublePendulumDrift(Integrator::RK4, 2e-3);
  std::cout << "[ measured ] RK4 energy drift dt 4e-3: " << coarse << " J, dt 2e-3: " << fine << " J, ratio "
            << coarse / fine << " (4th order: 16)\n";
  EXPECT_GT(coarse / fine, 10.0);
  EXPECT_LT(coarse / fine, 40.0);
}

// The shipped damped pendulum: E non-increasing, and E(0) - E(t) = integral of damping * alpha^2.
TEST(ScenePhysics, EnergyDecaysByTheDampingWork)
{
  Model<double> m(sceneFromText(R"(<scene name="d"><robot urdf="pendulum.urdf"/>
    <joints><joint name="joint1" damping="0.5"/></joints>
    <simulation><initial joint="joint1" q="1.0"/></simulation></scene>)"));
  SceneState<double> s = initialState(m.dyn);
  const double dt = 1e-3, E0 = totalEnergy(m.dyn, s);
  double E = E0, work = 0, prevPower = 0;
  bool monotone = true;
  simulate(m.dyn, s, 5000, dt, Integrator::RK4, [&](long, const SceneState<double> & st) {
    const double power = 0.5 * st.alpha[0] * st.alpha[0];
    work += 0.5 * dt * (power + prevPower); // trapezoid of the dissipated power
    prevPower = power;
    const double En = totalEnergy(m.dyn, st);
    monotone = monotone && En <= E + 1e-12;
    E = En;
  });
  std::cout << "[ measured ] damped pendulum 5 s: E " << E0 << " -> " << E << " J, damping work " << work
            << " J, balance error " << std::abs(E0 - E - work) << " J\n";
  EXPECT_TRUE(monotone);
  EXPECT_LT(E - (-9.81), 0.5 * (E0 - (-9.81))); // more than half the swing energy is gone
  EXPECT_NEAR(E0 - E, work, 1e-5);
}

// Small angle: I th'' + c th' + m g l th = 0, I = m l^2 + I_yy (robots/pendulum.urdf: m = 1, l = 1,
// I_yy = 4e-5): th(t) = e^{-z w t} (th0 cos(wd t) + z w th0 / wd sin(wd t)).
TEST(ScenePhysics, DampedPendulumMatchesClosedForm)
{
  const double th0 = 0.01, c = 0.3;
  Model<double> m(sceneFromText(R"(<scene name="d"><robot urdf="pendulum.urdf"/>
    <joints><joint name="joint1" damping="0.3"/></joints>
    <simulation><initial joint="joint1" q="0.01"/></simulation></scene>)"));
  const double I = 1 + 4e-5, w = std::sqrt(9.81 / I), z = c / (2 * std::sqrt(I * 9.81)), wd = w * std::sqrt(1 - z * z);
  SceneState<double> s = initialState(m.dyn);
  const double dt = 1e-3;
  double worst = 0;
  simulate(m.dyn, s, 5000, dt, Integrator::RK4, [&](long k, const SceneState<double> & st) {
    const double t = static_cast<double>(k) * dt;
    const double th = std::exp(-z * w * t) * (th0 * std::cos(wd * t) + z * w * th0 / wd * std::sin(wd * t));
    worst = std::max(worst, std::abs(st.q[0] - th));
  });
  // sin th = th (1 - th^2/6): the nonlinearity shifts the frequency by ~th0^2/16 (6e-6 relative)
  std::cout << "[ measured ] damped pendulum vs closed form, 5 s: max |th - th_cf| = " << worst << " rad (th0 = "
            << th0 << ")\n";
  EXPECT_LT(worst, 2e-4 * th0);
}

// Zero gravity, no damping, no contacts: centroidal momentum constant, CoM moving uniformly.
TEST(ScenePhysics, MomentumConservedInZeroGravity)
{
  Model<double> m(loadScene(scenesDir() + "/humanoid_zero_gravity.xml"));
  SceneState<double> s = initialState(m.dyn);
  const Eigen::Matrix<double, 6, 1> h0 = m.dyn.centroidalMomentum(s.q, s.alpha).vector();
  const Eigen::Vector3d c0 = m.dyn.centerOfMass(s.q);
  const double M = m.dyn.totalMass(), E0 = totalEnergy(m.dyn, s);
  ASSERT_GT(h0.norm(), 0.1);
  double worstH = 0;
  const double dt = m.scene.dt;
  const long steps = 1000;
  simulate(m.dyn, s, steps, dt, m.scene.integrator, [&](long, const SceneState<double> & st) {
    worstH = std::max(worstH, (m.dyn.centroidalMomentum(st.q, st.alpha).vector() - h0).norm() / h0.norm());
  });
  const Eigen::Vector3d c1 = m.dyn.centerOfMass(s.q), expected = c0 + h0.tail<3>() / M * (static_cast<double>(steps) * dt);
  std::cout << "[ measured ] humanoid zero gravity, 1 s RK4 dt 1e-3: max |h - h0|/|h0| = " << worstH << ", CoM error "
            << (c1 - expected).norm() << " m, energy drift " << std::abs(totalEnergy(m.dyn, s) - E0) << " J\n";
  EXPECT_LT(worstH, 1e-6);
  EXPECT_LT((c1 - expected).norm(), 1e-7);
}

// A 2 kg box on four corner contacts settles: each corner carries m g / 4, the penetration is
// m g / (4 k), nothing slides or explodes.
TEST(ScenePhysics, BoxSettlesOnContacts)
{
  const fs::path dir = fs::temp_directory_path() / ("rbdgen_scene_box_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "box.urdf") << R"(<robot name="box"><link name="box"><inertial><origin xyz="0 0 0"/>
    <mass value="2"/><inertia ixx="0.0083" ixy="0" ixz="0" iyy="0.0167" iyz="0" izz="0.0217"/></inertial></link></robot>)";
  std::ofstream(dir / "box.xml") << R"(<scene name="box"><robot urdf="box.urdf" base="floating"/>
  <contacts stiffness="10000" damping="200" mu="0.5" slip_velocity="0.01">
    <point name="a" body="box" xyz="0.1 0.05 -0.05"/> <point name="b" body="box" xyz="-0.1 0.05 -0.05"/>
    <point name="c" body="box" xyz="0.1 -0.05 -0.05"/> <point name="d" body="box" xyz="-0.1 -0.05 -0.05"/>
  </contacts>
  <simulation><initial joint="Root" q="1 0 0 0 0 0 0.07" alpha="0.3 -0.2 0.1 0.2 0.1 0"/></simulation></scene>)";
  Model<double> m(loadScene((dir / "box.xml").string()));
  fs::remove_all(dir);
  SceneState<double> s = initialState(m.dyn);
  double maxSpeed = 0;
  simulate(m.dyn, s, 3000, 1e-3, Integrator::SemiImplicitEuler,
           [&](long, const SceneState<double> & st) { maxSpeed = std::max(maxSpeed, st.alpha.norm()); });
  const auto f = m.dyn.contactForces(s.q, s.alpha);
  const double mg = 2 * 9.81;
  double sum = 0;
  for(const auto & fc : f)
  {
    EXPECT_NEAR(fc.z(), mg / 4, 1e-3 * mg) << "each corner carries a quarter";
    EXPECT_LT(fc.head<2>().norm(), 1e-3 * mg) << "no sliding force at rest";
    sum += fc.z();
  }
  std::cout << "[ measured ] box after 3 s: sum fn = " << sum << " N (m g = " << mg << "), |alpha| = " << s.alpha.norm()
            << ", height " << s.q[6] << " m (expected 0.05 - m g/(4k) = " << 0.05 - mg / 4 / 1e4 << ")\n";
  EXPECT_NEAR(sum, mg, 1e-6 * mg);
  EXPECT_LT(s.alpha.norm(), 1e-4);
  EXPECT_NEAR(s.q[6], 0.05 - mg / 4 / 1e4, 1e-6);
  EXPECT_LT(maxSpeed, 10.0); // no explosion
}

// The shipped standing quadruped settles: at rest, the normal forces carry its weight (statics).
TEST(ScenePhysics, QuadrupedStandingSettles)
{
  Model<double> m(loadScene(scenesDir() + "/quadruped_standing.xml"));
  SceneState<double> s = initialState(m.dyn);
  double maxKinetic = 0;
  simulate(m.dyn, s, std::lround(m.scene.duration / m.scene.dt), m.scene.dt, m.scene.integrator,
           [&](long, const SceneState<double> & st) { maxKinetic = std::max(maxKinetic, m.dyn.kineticEnergy(st.q, st.alpha)); });
  double sum = 0;
  for(const auto & f : m.dyn.contactForces(s.q, s.alpha)) sum += f.z();
  const double mg = m.dyn.totalMass() * 9.81;
  std::cout << "[ measured ] quadruped standing after " << m.scene.duration << " s: sum fn = " << sum << " N (m g = " << mg
            << "), |alpha| = " << s.alpha.norm() << ", trunk z = " << s.q[6] << " m, max kinetic " << maxKinetic << " J\n";
  EXPECT_NEAR(sum, mg, 1e-3 * mg);
  EXPECT_LT(s.alpha.norm(), 1e-2);
  EXPECT_GT(s.q[6], 0.2);
  EXPECT_LT(maxKinetic, 1.0);
}

// Zero torque: the quadruped falls, folds and comes to rest on the ground without passing through it.
TEST(ScenePhysics, QuadrupedFallingComesToRest)
{
  Model<double> m(loadScene(scenesDir() + "/quadruped_falling.xml"));
  SceneState<double> s = initialState(m.dyn);
  double minZ = 1;
  simulate(m.dyn, s, std::lround(m.scene.duration / m.scene.dt), m.scene.dt, m.scene.integrator,
           [&](long, const SceneState<double> & st) { minZ = std::min(minZ, st.q[6]); });
  double sum = 0;
  for(const auto & f : m.dyn.contactForces(s.q, s.alpha)) sum += f.z();
  const double mg = m.dyn.totalMass() * 9.81;
  std::cout << "[ measured ] quadruped falling after " << m.scene.duration << " s: lowest trunk z " << minZ
            << " m, kinetic " << m.dyn.kineticEnergy(s.q, s.alpha) << " J, sum fn " << sum << " N (m g = " << mg << ")\n";
  EXPECT_GT(minZ, 0.0);
  EXPECT_LT(m.dyn.kineticEnergy(s.q, s.alpha), 0.05);
  EXPECT_NEAR(sum, mg, 0.02 * mg);
}

TEST(ScenePhysics, EveryShippedSceneLoadsAndSimulates)
{
  int n = 0;
  for(const auto & e : fs::directory_iterator(scenesDir()))
  {
    if(e.path().extension() != ".xml") continue;
    ++n;
    Model<double> m(loadScene(e.path().string()));
    SceneState<double> s = initialState(m.dyn);
    try
    {
      simulate(m.dyn, s, 200, m.scene.dt, m.scene.integrator, [](long, const SceneState<double> &) {});
    }
    catch(const std::exception & err)
    {
      ADD_FAILURE() << e.path() << ": " << err.what();
    }
    EXPECT_TRUE(s.q.allFinite() && s.alpha.allFinite()) << e.path();
    EXPECT_TRUE(std::isfinite(totalEnergy(m.dyn, s))) << e.path();
  }
  EXPECT_GE(n, 5);
}

// pd_gravity with zero gains is pure gravity compensation: tau = g(q) holds the arm still.
TEST(ScenePhysics, GravityCompensationHoldsTheArm)
{
  Model<double> m(sceneFromText(R"(<scene name="g"><robot urdf="ur5e.urdf"/><joints damping="none" friction="none"/>
    <simulation><initial joint="shoulder_lift_joint" q="-1.2"/><initial joint="elbow_joint" q="1.0"/>
    <controller type="pd_gravity"/></simulation></scene>)"));
  SceneState<double> s = initialState(m.dyn);
  const Eigen::VectorXd q0 = s.q;
  ASSERT_GT(m.dyn.gravityTorques(q0).norm(), 10.0);
  simulate(m.dyn, s, 1000, 1e-3, Integrator::SemiImplicitEuler, [](long, const SceneState<double> &) {});
  EXPECT_LT((s.q - q0).norm(), 1e-10);
  // with zero torque instead, the arm falls
  Model<double> falls(sceneFromText(R"(<scene name="g"><robot urdf="ur5e.urdf"/><joints damping="none" friction="none"/>
    <simulation><initial joint="shoulder_lift_joint" q="-1.2"/><initial joint="elbow_joint" q="1.0"/></simulation></scene>)"));
  SceneState<double> f = initialState(falls.dyn);
  simulate(falls.dyn, f, 1000, 1e-3, Integrator::SemiImplicitEuler, [](long, const SceneState<double> &) {});
  EXPECT_GT((f.q - q0).norm(), 0.1);
}

// One step of each integrator on the damped pendulum against the same update written by hand on
// the scalar ODE I th'' = tau - c th' - m g l sin(th) (robots/pendulum.urdf: m = 1, l = 1).
TEST(ScenePhysics, IntegratorStepsMatchTheirDefinition)
{
  Model<double> m(sceneFromText(R"(<scene name="p"><robot urdf="pendulum.urdf"/>
    <joints><joint name="joint1" damping="0.4" armature="0.1"/></joints></scene>)"));
  const double I = 1 + 4e-5 + 0.1, c = 0.4, tau = 0.3, dt = 0.01;
  auto acc = [&](double th, double w) { return (tau - c * w - 9.81 * std::sin(th)) / I; };
  const double th0 = 0.7, w0 = -1.3;
  struct Case
  {
    Integrator integ;
    double th, w;
  };
  // hand-written updates
  const double aE = acc(th0, w0);
  const double k1t = w0, k1w = aE;
  const double k2t = w0 + dt / 2 * k1w, k2w = acc(th0 + dt / 2 * k1t, w0 + dt / 2 * k1w);
  const double k3t = w0 + dt / 2 * k2w, k3w = acc(th0 + dt / 2 * k2t, w0 + dt / 2 * k2w);
  const double k4t = w0 + dt * k3w, k4w = acc(th0 + dt * k3t, w0 + dt * k3w);
  for(const Case & cs : {Case{Integrator::SemiImplicitEuler, th0 + dt * (w0 + dt * aE), w0 + dt * aE},
                         Case{Integrator::ExplicitEuler, th0 + dt * w0, w0 + dt * aE},
                         Case{Integrator::RK4, th0 + dt / 6 * (k1t + 2 * k2t + 2 * k3t + k4t),
                              w0 + dt / 6 * (k1w + 2 * k2w + 2 * k3w + k4w)}})
  {
    SceneState<double> s{Eigen::VectorXd::Constant(1, th0), Eigen::VectorXd::Constant(1, w0)};
    step(m.dyn, s, Eigen::VectorXd::Constant(1, tau), dt, cs.integ);
    EXPECT_NEAR(s.q[0], cs.th, 1e-14) << integratorName(cs.integ);
    EXPECT_NEAR(s.alpha[0], cs.w, 1e-14) << integratorName(cs.integ);
  }
}
