// The runtime evaluation of a scene (rbd::scene::SceneDynamics) against independent truths:
// FD(ID(a)) = a, the power balance (finite differences in time, long double), locked joints
// against the full robot restricted to the free dofs, a rotated gravity against a rotated world,
// the contact model formula with finite-difference velocities, the wrench convention via the
// momentum rate, Jacobians via finite differences of the pose.
#include <random>

#include <rbd/FD.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/parsers/urdf.h>

#include "SceneTestUtils.h"

using namespace scenetest;
using rbd::scene::SceneDynamicsTpl;
using LD = long double;

namespace
{

/// The quadruped with every effect: damping, friction, armature, contacts, two external wrenches.
std::string quadrupedAllEffects(bool velocityTerms = true)
{
  return sceneXml("quadruped.urdf",
                  std::string("  <velocity_terms enabled=\"") + (velocityTerms ? "true" : "false") + "\"/>\n" +
                      R"(  <joints friction_velocity="0.05">
    <joint name="FL_hip_joint" armature="0.01" damping="0.3"/>
    <joint name="HR_calf_joint" armature="0.02" friction="0.5"/>
  </joints>
  <external_wrench body="trunk"/>
  <external_wrench body="FR_calf"/>
  <contacts stiffness="20000" damping="300" mu="0.8" slip_velocity="0.01" ground_height="0.05">
    <point name="FL" body="FL_foot"/> <point name="FR" body="FR_foot"/>
    <point name="HL" body="HL_foot"/> <point name="HR" body="HR_foot" xyz="0.01 0 0"/>
    <point name="knee" body="FL_calf"/>
  </contacts>)",
                  "floating");
}

/// Random state of the quadruped with the trunk low enough for some contacts to penetrate.
template<class T>
rbd::scene::SceneState<T> quadrupedState(const rbd::MultiBodyTpl<T> & mb, std::mt19937 & rng)
{
  auto s = randomState<T>(mb, rng, 1.0);
  std::uniform_real_distribution<double> z(0.05, 0.3);
  s.q[6] = T(z(rng));
  return s;
}

template<class T>
std::vector<sva::ForceVec<T>> randomWrenches(std::size_t n, std::mt19937 & rng)
{
  std::vector<sva::ForceVec<T>> w;
  for(std::size_t k = 0; k < n; ++k) w.emplace_back(Eigen::Matrix<T, 6, 1>(randomVector<T>(6, rng, 5.0)));
  return w;
}

} // namespace

TEST(SceneDynamics, ForwardInverseRoundTrip)
{
  std::mt19937 rng(1);
  const std::vector<std::string> scenes = {
      quadrupedAllEffects(true), quadrupedAllEffects(false),
      sceneXml("ur5e.urdf", "<velocity_terms enabled=\"false\"/><joints><joint name=\"elbow_joint\" armature=\"0.1\"/></joints>"),
      sceneXml("humanoid.urdf", "<gravity enabled=\"false\"/>", "floating")};
  double worst = 0;
  for(const std::string & xml : scenes)
  {
    Model<double> m(sceneFromText(xml));
    for(int trial = 0; trial < 20; ++trial)
    {
      auto s = m.scene.contacts.empty() ? randomState<double>(m.dyn.mb(), rng) : quadrupedState<double>(m.dyn.mb(), rng);
      const auto w = randomWrenches<double>(m.scene.externalWrenches.size(), rng);
      const Eigen::VectorXd a = randomVector<double>(m.dyn.nv(), rng, 3.0);
      const Eigen::VectorXd tau = m.dyn.inverseDynamics(s.q, s.alpha, a, w);
      const Eigen::VectorXd a2 = m.dyn.forwardDynamics(s.q, s.alpha, tau, w);
      // relative to the size of H^-1 tau: cond(H) eps
      const double e = relErr(a2, a);
      worst = std::max(worst, e);
      EXPECT_LT(e, 1e-7) << xml;
    }
  }
  std::cout << "[ measured ] FD(ID(a)) = a: worst relative error " << worst << "\n";
}

// d(T + V)/dt = alpha.tau - alpha.D.alpha - alpha.f_c + sum F_c.v_c + sum W.V_body, with the
// derivative of the energy taken by central differences along the motion (q ⊕ ±h alpha, alpha ± h a).
TEST(SceneDynamics, PowerBalance)
{
  std::mt19937 rng(2);
  for(const std::string & xml :
      {quadrupedAllEffects(true), sceneXml("humanoid.urdf", "<gravity x=\"1\" y=\"-2\" z=\"-3\"/>", "floating"),
       sceneXml("ur5e.urdf", "<joints><joint name=\"wrist_1_joint\" armature=\"0.05\" friction=\"0.7\"/></joints>")})
  {
    Model<LD> m(sceneFromText(xml));
    const auto & dyn = m.dyn;
    double worst = 0;
    for(int trial = 0; trial < 10; ++trial)
    {
      auto s = m.scene.contacts.empty() ? randomState<LD>(dyn.mb(), rng) : quadrupedState<LD>(dyn.mb(), rng);
      const auto w = randomWrenches<LD>(m.scene.externalWrenches.size(), rng);
      const VecX<LD> tau = randomVector<LD>(dyn.nv(), rng, 5.0);
      const VecX<LD> a = dyn.forwardDynamics(s.q, s.alpha, tau, w);
      auto energy = [&](LD h) {
        const VecX<LD> q = rbd::integrateConfiguration(dyn.mb(), s.q, VecX<LD>(s.alpha * h));
        const VecX<LD> al = s.alpha + a * h;
        return dyn.kineticEnergy(q, al) + dyn.potentialEnergy(q);
      };
      const LD h = 1e-8L;
      const LD dE = (energy(h) - energy(-h)) / (2 * h);
      // the power of every non-conservative force
      LD P = s.alpha.dot(tau);
      const LD vs = LD(m.scene.frictionVelocity);
      for(int i = 0; i < dyn.nv(); ++i)
      {
        const LD al = s.alpha[i];
        P -= dyn.damping()[i] * al * al + dyn.friction()[i] * al * al / std::sqrt(al * al + vs * vs);
      }
      const auto F = dyn.contactForces(s.q, s.alpha);
      const auto v = dyn.contactVelocities(s.q, s.alpha);
      for(std::size_t c = 0; c < F.size(); ++c) P += F[c].dot(v[c]);
      const auto mbc = dyn.kinematics(s.q, s.alpha);
      for(std::size_t k = 0; k < w.size(); ++k)
      {
        const auto b = static_cast<std::size_t>(m.robot.wrenchBodies[k]);
        P += mbc.bodyPosW[b].dualMul(w[k]).dot(mbc.bodyVelB[b]); // W (world origin) . V (world origin)
      }
      const double scale = std::max(1.0, static_cast<double>(std::abs(P)));
      const double e = static_cast<double>(std::abs(dE - P)) / scale;
      worst = std::max(worst, e);
      EXPECT_LT(e, 1e-8) << xml << " dE/dt " << static_cast<double>(dE) << " power " << static_cast<double>(P);
    }
    std::cout << "[ measured ] power balance " << m.robot.robot.name << ": worst relative error " << worst << "\n";
  }
}

TEST(SceneDynamics, ContactVelocitiesAreTimeDerivatives)
{
  std::mt19937 rng(3);
  Model<LD> m(sceneFromText(quadrupedAllEffects()));
  for(int trial = 0; trial < 5; ++trial)
  {
    auto s = quadrupedState<LD>(m.dyn.mb(), rng);
    const LD h = 1e-7L;
    const auto pp = m.dyn.contactPositions(rbd::integrateConfiguration(m.dyn.mb(), s.q, VecX<LD>(s.alpha * h)));
    const auto pm = m.dyn.contactPositions(rbd::integrateConfiguration(m.dyn.mb(), s.q, VecX<LD>(-s.alpha * h)));
    const auto v = m.dyn.contactVelocities(s.q, s.alpha);
    for(std::size_t c = 0; c < v.size(); ++c) EXPECT_LT(relErr(v[c], Eigen::Matrix<LD, 3, 1>((pp[c] - pm[c]) / (2 * h))), 1e-9);
  }
}

// The contact law of Scene.h, evaluated here from the link poses and finite-difference velocities.
TEST(SceneDynamics, ContactForceFormula)
{
  std::mt19937 rng(4);
  Model<LD> m(sceneFromText(quadrupedAllEffects()));
  const auto & cm = m.scene.contactModel;
  int penetrating = 0, total = 0;
  for(int trial = 0; trial < 30; ++trial)
  {
    auto s = quadrupedState<LD>(m.dyn.mb(), rng);
    const auto F = m.dyn.contactForces(s.q, s.alpha);
    for(std::size_t c = 0; c < m.scene.contacts.size(); ++c)
    {
      const auto & pt = m.scene.contacts[c];
      auto pointAt = [&](LD h) {
        const auto X = m.dyn.pose(rbd::integrateConfiguration(m.dyn.mb(), s.q, VecX<LD>(s.alpha * h)), pt.body);
        return Eigen::Matrix<LD, 3, 1>(X.translation() + X.rotation().transpose() * pt.point.cast<LD>());
      };
      const LD h = 1e-7L;
      const Eigen::Matrix<LD, 3, 1> p = pointAt(0), v = (pointAt(h) - pointAt(-h)) / (2 * h);
      const LD d = LD(cm.groundHeight) - p.z();
      Eigen::Matrix<LD, 3, 1> f = Eigen::Matrix<LD, 3, 1>::Zero();
      const LD fn = std::max(LD(0), LD(cm.stiffness) * d - LD(cm.damping) * v.z());
      if(d > 0 && fn > 0)
      {
        const LD vt = std::sqrt(v.x() * v.x() + v.y() * v.y() + LD(cm.slipVelocity * cm.slipVelocity));
        f = Eigen::Matrix<LD, 3, 1>(-LD(cm.mu) * fn * v.x() / vt, -LD(cm.mu) * fn * v.y() / vt, fn);
        ++penetrating;
      }
      ++total;
      EXPECT_LT(relErr(F[c], f), 1e-7) << pt.name;
    }
  }
  EXPECT_GT(penetrating, total / 10) << "the states should exercise penetrating contacts";
  EXPECT_LT(penetrating, total) << "and separated ones";
}

// A wrench at the world origin on the resting floating robot in zero gravity: dh_G/dt = the wrench
// moved to the CoM (finite differences of the centroidal momentum).
TEST(SceneDynamics, ExternalWrenchConvention)
{
  std::mt19937 rng(5);
  Model<LD> m(sceneFromText(sceneXml("quadruped.urdf", R"(<gravity enabled="false"/><joints damping="none" friction="none"/>
      <external_wrench body="FL_calf"/>)", "floating")));
  for(int trial = 0; trial < 5; ++trial)
  {
    auto s = randomState<LD>(m.dyn.mb(), rng);
    s.alpha.setZero();
    const auto w = randomWrenches<LD>(1, rng);
    const VecX<LD> a = m.dyn.forwardDynamics(s.q, s.alpha, VecX<LD>::Zero(m.dyn.nv()), w);
    const LD h = 1e-6L;
    auto momentum = [&](LD t) {
      return m.dyn.centroidalMomentum(rbd::integrateConfiguration(m.dyn.mb(), s.q, VecX<LD>(s.alpha * t)), VecX<LD>(a * t)).vector();
    };
    const Eigen::Matrix<LD, 6, 1> hd = (momentum(h) - momentum(-h)) / (2 * h);
    const Eigen::Matrix<LD, 3, 1> c = m.dyn.centerOfMass(s.q);
    Eigen::Matrix<LD, 6, 1> expected;
    expected << w[0].couple() - c.cross(w[0].force()), w[0].force();
    EXPECT_LT(relErr(hd, expected), 1e-8);
  }
}

TEST(SceneDynamics, VelocityTermsOffKeepsGravityOnly)
{
  std::mt19937 rng(6);
  Model<double> off(sceneFromText(sceneXml("ur5e.urdf", "<velocity_terms enabled=\"false\"/><joints damping=\"none\" friction=\"none\"/>")));
  Model<double> on(sceneFromText(sceneXml("ur5e.urdf", "<joints damping=\"none\" friction=\"none\"/>")));
  for(int trial = 0; trial < 10; ++trial)
  {
    auto s = randomState<double>(on.dyn.mb(), rng);
    const Eigen::VectorXd tau = randomVector<double>(on.dyn.nv(), rng, 10);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(on.dyn.nv());
    EXPECT_LT(relErr(off.dyn.forwardDynamics(s.q, s.alpha, tau), on.dyn.forwardDynamics(s.q, zero, tau)), 1e-12);
    EXPECT_GT(relErr(on.dyn.forwardDynamics(s.q, s.alpha, tau), on.dyn.forwardDynamics(s.q, zero, tau)), 1e-6);
  }
  Model<double> none(sceneFromText(sceneXml("ur5e.urdf", "<gravity enabled=\"false\"/>")));
  const auto s = randomState<double>(none.dyn.mb(), rng);
  EXPECT_EQ(none.dyn.potentialEnergy(s.q), 0.0);
  EXPECT_LT(none.dyn.forwardDynamics(s.q, Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6)).norm(), 1e-14);
}

// Gravity g' = R g0 on a floating robot equals gravity g0 in the world rotated by R^T: base pose
// (R^T Q, R^T p), body-frame velocities unchanged, the same accelerations.
TEST(SceneDynamics, RotatedGravityIsARotatedWorld)
{
  std::mt19937 rng(7);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d g = R * Eigen::Vector3d(0, 0, -9.81);
  std::ostringstream gx;
  gx << std::setprecision(17) << "<gravity x=\"" << g.x() << "\" y=\"" << g.y() << "\" z=\"" << g.z() << "\"/>";
  Model<double> rotated(sceneFromText(sceneXml("quadruped.urdf", gx.str(), "floating")));
  Model<double> plain(sceneFromText(sceneXml("quadruped.urdf", "", "floating")));
  double worst = 0;
  for(int trial = 0; trial < 10; ++trial)
  {
    auto s = randomState<double>(plain.dyn.mb(), rng);
    const Eigen::VectorXd tau = randomVector<double>(plain.dyn.nv(), rng, 3);
    Eigen::VectorXd q0 = s.q;
    const Eigen::Quaterniond Q(s.q[0], s.q[1], s.q[2], s.q[3]);
    const Eigen::Quaterniond Q0(Eigen::Matrix3d(R.transpose() * Q.toRotationMatrix()));
    q0.head<4>() << Q0.w(), Q0.x(), Q0.y(), Q0.z();
    q0.segment<3>(4) = R.transpose() * s.q.segment<3>(4);
    const double e = relErr(rotated.dyn.forwardDynamics(s.q, s.alpha, tau), plain.dyn.forwardDynamics(q0, s.alpha, tau));
    worst = std::max(worst, e);
    EXPECT_LT(e, 1e-10);
    EXPECT_NEAR(rotated.dyn.potentialEnergy(s.q), plain.dyn.potentialEnergy(q0), 1e-10);
  }
  std::cout << "[ measured ] rotated gravity vs rotated world: worst relative error " << worst << "\n";
}

// Locked joints: the scene's H and b equal the full robot's (loaded directly, no fixJoints) at the
// held value with zero locked velocity, restricted to the free dofs; link poses agree.
TEST(SceneDynamics, LockedJointsEqualRestrictedFullRobot)
{
  std::mt19937 rng(8);
  struct Case
  {
    std::string urdf, base, locks, link;
    std::map<std::string, double> held;
  };
  const std::vector<Case> cases = {
      {"ur5e.urdf", "fixed", R"(<lock name="elbow_joint" position="0.7"/><lock name="wrist_2_joint" position="-0.4"/>)",
       "tool0", {{"elbow_joint", 0.7}, {"wrist_2_joint", -0.4}}},
      {"quadruped.urdf", "floating", R"(<lock name="FL_calf_joint" position="1.2"/><lock name="HR_hip_joint" position="-0.3"/>)",
       "FL_foot", {{"FL_calf_joint", 1.2}, {"HR_hip_joint", -0.3}}}};
  for(const Case & c : cases)
  {
    Model<double> m(sceneFromText(sceneXml(c.urdf, "<joints damping=\"none\" friction=\"none\">" + c.locks + "</joints>", c.base)));
    rbd::parsers::ParserOptions opt;
    opt.fixed = c.base == "fixed";
    const auto full = rbd::parsers::fromUrdfFile(robotsDir() + "/" + c.urdf, opt);
    ASSERT_EQ(m.dyn.nv() + static_cast<int>(c.held.size()), full.mb.nrDof());
    for(int trial = 0; trial < 5; ++trial)
    {
      auto s = randomState<double>(m.dyn.mb(), rng);
      // the full configuration: scene joints by name, locked joints at their held value
      rbd::MultiBodyConfig mbc(full.mb);
      std::vector<Eigen::Index> freeDofs, sceneDofs; // the same dof in the full robot and in the scene
      for(int i = 0; i < full.mb.nrJoints(); ++i)
      {
        const auto & j = full.mb.joint(i);
        const auto k = static_cast<std::size_t>(i);
        if(auto it = c.held.find(j.name()); it != c.held.end())
        {
          mbc.q[k] = {it->second};
          mbc.alpha[k] = {0.0};
          continue;
        }
        const int si = m.dyn.mb().jointIndexByName(j.name());
        for(int p = 0; p < j.params(); ++p) mbc.q[k][static_cast<std::size_t>(p)] = s.q[m.dyn.mb().jointPosInParam(si) + p];
        for(int d = 0; d < j.dof(); ++d)
        {
          mbc.alpha[k][static_cast<std::size_t>(d)] = s.alpha[m.dyn.mb().jointPosInDof(si) + d];
          freeDofs.push_back(full.mb.jointPosInDof(i) + d);
          sceneDofs.push_back(m.dyn.mb().jointPosInDof(si) + d);
        }
      }
      rbd::forwardKinematics(full.mb, mbc);
      rbd::forwardVelocity(full.mb, mbc);
      rbd::ForwardDynamics fd(full.mb);
      fd.computeH(full.mb, mbc);
      fd.computeC(full.mb, mbc);
      const auto n = static_cast<Eigen::Index>(freeDofs.size());
      ASSERT_EQ(n, m.dyn.nv());
      Eigen::MatrixXd H(n, n);
      Eigen::VectorXd b(n);
      for(std::size_t r = 0; r < freeDofs.size(); ++r)
      {
        b[sceneDofs[r]] = fd.C()[freeDofs[r]];
        for(std::size_t col = 0; col < freeDofs.size(); ++col) H(sceneDofs[r], sceneDofs[col]) = fd.H()(freeDofs[r], freeDofs[col]);
      }
      EXPECT_LT(relErr(m.dyn.massMatrix(s.q), H), 1e-12) << c.urdf;
      EXPECT_LT(relErr(m.dyn.generalizedBias(s.q, s.alpha), b), 1e-12) << c.urdf;
      const auto X = m.dyn.pose(s.q, c.link);
      const auto & Xf = mbc.bodyPosW[static_cast<std::size_t>(full.mb.bodyIndexByName(c.link))];
      EXPECT_LT(relErr(X.matrix(), Xf.matrix()), 1e-12) << c.link;
    }
  }
}

// J alpha = [w; v] of the link origin, world axes, against finite differences of the pose.
TEST(SceneDynamics, JacobianIsPoseDerivative)
{
  std::mt19937 rng(9);
  Model<LD> m(sceneFromText(sceneXml("quadruped.urdf", R"(<joints><lock name="FL_calf_joint" position="0.9"/></joints>)", "floating")));
  for(const std::string link : {"FL_foot", "FL_calf", "HR_calf", "trunk"})
    for(int trial = 0; trial < 3; ++trial)
    {
      auto s = randomState<LD>(m.dyn.mb(), rng);
      const LD h = 1e-7L;
      const auto Xp = m.dyn.pose(rbd::integrateConfiguration(m.dyn.mb(), s.q, VecX<LD>(s.alpha * h)), link);
      const auto Xm = m.dyn.pose(rbd::integrateConfiguration(m.dyn.mb(), s.q, VecX<LD>(-s.alpha * h)), link);
      const auto X = m.dyn.pose(s.q, link);
      // R = E^T (link to world); w^ = Rdot R^T
      const Eigen::Matrix<LD, 3, 3> Rdot = (Xp.rotation().transpose() - Xm.rotation().transpose()) / (2 * h);
      const Eigen::Matrix<LD, 3, 3> W = Rdot * X.rotation();
      Eigen::Matrix<LD, 6, 1> expected;
      expected << W(2, 1), W(0, 2), W(1, 0), (Xp.translation() - Xm.translation()) / (2 * h);
      EXPECT_LT(relErr(Eigen::Matrix<LD, 6, 1>(m.dyn.jacobian(s.q, link) * s.alpha), expected), 1e-9) << link;
    }
}

// Linear momentum = M dc/dt (finite differences of the CoM); kinetic energy with armature.
TEST(SceneDynamics, MomentumAndEnergyDefinitions)
{
  std::mt19937 rng(10);
  Model<LD> m(sceneFromText(sceneXml("quadruped.urdf", R"(<joints><joint name="FR_thigh_joint" armature="0.3"/></joints>)", "floating")));
  auto s = randomState<LD>(m.dyn.mb(), rng);
  const LD h = 1e-7L;
  const Eigen::Matrix<LD, 3, 1> cd =
      (m.dyn.centerOfMass(rbd::integrateConfiguration(m.dyn.mb(), s.q, VecX<LD>(s.alpha * h))) -
       m.dyn.centerOfMass(rbd::integrateConfiguration(m.dyn.mb(), s.q, VecX<LD>(-s.alpha * h)))) / (2 * h);
  EXPECT_LT(relErr(m.dyn.centroidalMomentum(s.q, s.alpha).force(), Eigen::Matrix<LD, 3, 1>(m.dyn.totalMass() * cd)), 1e-9);
  EXPECT_NEAR(static_cast<double>(m.dyn.totalMass()), 8.252, 1e-12); // robots/quadruped.urdf: 3.3 + 4 (0.54 + 0.634 + 0.064)
  // armature adds 1/2 armature alpha_i^2 to the rigid-body kinetic energy
  Model<LD> bare(sceneFromText(sceneXml("quadruped.urdf", "", "floating")));
  const int i = m.dyn.mb().jointPosInDof(m.dyn.mb().jointIndexByName("FR_thigh_joint"));
  EXPECT_NEAR(static_cast<double>(m.dyn.kineticEnergy(s.q, s.alpha) - bare.dyn.kineticEnergy(s.q, s.alpha)),
              static_cast<double>(0.5L * 0.3L * s.alpha[i] * s.alpha[i]), 1e-15);
}

// Scene derivatives (inverse and forward dynamics; wrenches held constant) against long double
// Richardson central differences along q ⊕ ε e_m and alpha + ε e_m: every effect but contacts,
// velocity terms on and off. Truncation O(h^4) with h = 1e-3, round-off 1e-19/h: bound 1e-9 (ID),
// 1e-7 (FD: M^-1 amplifies).
TEST(SceneDynamics, DerivativesMatchLongDoubleDifferences)
{
  // df/dt at 0: central differences with one Richardson step (error O(h^4))
  auto richardson = [](auto f, LD h) {
    const VecX<LD> d1 = (f(h) - f(-h)) / (2 * h), d2 = (f(h / 2) - f(-h / 2)) / h;
    return VecX<LD>((4 * d2 - d1) / 3);
  };
  std::mt19937 rng(21);
  const char * effects = R"(  <gravity x="0.4" y="-1" z="-9.81"/>
  <joints friction_velocity="0.05">
    <joint name="FL_hip_joint" armature="0.01" damping="0.3" friction="0.2"/>
    <joint name="HR_calf_joint" armature="0.02" friction="0.5"/>
  </joints>
  <external_wrench body="trunk"/>
  <external_wrench body="FR_calf"/>)";
  // the quadruped with tilted gravity, joint effects and wrenches, velocity terms on and off; then
  // with its compliant contacts (states away from the contact boundaries, where F has a kink)
  for(int variant = 0; variant < 3; ++variant)
  {
    const bool velocity = variant != 1, contacts = variant == 2;
    const std::string xml =
        contacts ? quadrupedAllEffects(true)
                 : sceneXml("quadruped.urdf",
                            std::string("<velocity_terms enabled=\"") + (velocity ? "true" : "false") + "\"/>" + effects, "floating");
    Model<LD> m(sceneFromText(xml));
    const auto & dyn = m.dyn;
    const int nv = dyn.nv();
    double worst[4] = {0, 0, 0, 0};
    int pushed = 0;
    for(int trial = 0; trial < 3; ++trial)
    {
      auto s = contacts ? quadrupedState<LD>(dyn.mb(), rng) : randomState<LD>(dyn.mb(), rng);
      if(contacts)
      {
        // k = 2e4, c = 300, z0 = 0.05 (quadrupedAllEffects): depth and push at least 1e-3 m and 1 N from 0
        const auto p = dyn.contactPositions(s.q);
        const auto v = dyn.contactVelocities(s.q, s.alpha);
        bool nearBoundary = false;
        int on = 0;
        for(std::size_t c = 0; c < p.size(); ++c)
        {
          const LD depth = 0.05L - p[c].z(), push = 2e4L * depth - 300.0L * v[c].z();
          nearBoundary = nearBoundary || std::abs(depth) < 1e-3L || (depth > 0 && std::abs(push) < 1.0L);
          on += depth > 0 && push > 0;
        }
        if(nearBoundary || on == 0)
        {
          --trial;
          continue;
        }
        pushed += on;
      }
      const auto w = randomWrenches<LD>(m.scene.externalWrenches.size(), rng);
      const VecX<LD> a = randomVector<LD>(nv, rng, 3.0), tau = randomVector<LD>(nv, rng, 5.0);
      const auto id = dyn.inverseDynamicsDerivatives(s.q, s.alpha, a, w);
      const auto fd = dyn.forwardDynamicsDerivatives(s.q, s.alpha, tau, w);
      Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic> nq(nv, nv), na(nv, nv), fq(nv, nv), fa(nv, nv);
      // friction alpha / sqrt(alpha^2 + vs^2) with vs = 0.05 has derivatives growing like vs^-k, and
      // the contacts are stiff (k = 2e4 N/m, slip velocity 0.01 m/s): small steps
      const LD h = contacts ? 1e-5L : 1e-3L, hAlpha = 1e-5L;
      for(int k = 0; k < nv; ++k)
      {
        const VecX<LD> e = VecX<LD>::Unit(nv, k);
        auto qAt = [&](LD t) { return rbd::integrateConfiguration(dyn.mb(), s.q, VecX<LD>(e * t)); };
        nq.col(k) = richardson([&](LD t) { return VecX<LD>(dyn.inverseDynamics(qAt(t), s.alpha, a, w)); }, h);
        na.col(k) = richardson([&](LD t) { return VecX<LD>(dyn.inverseDynamics(s.q, VecX<LD>(s.alpha + e * t), a, w)); }, hAlpha);
        fq.col(k) = richardson([&](LD t) { return VecX<LD>(dyn.forwardDynamics(qAt(t), s.alpha, tau, w)); }, h);
        fa.col(k) = richardson([&](LD t) { return VecX<LD>(dyn.forwardDynamics(s.q, VecX<LD>(s.alpha + e * t), tau, w)); }, hAlpha);
      }
      const double e[4] = {relErr(id.dtauDq, nq), relErr(id.dtauDalpha, na), relErr(fd.dalphaDDq, fq), relErr(fd.dalphaDDalpha, fa)};
      for(int i = 0; i < 4; ++i) worst[i] = std::max(worst[i], e[i]);
      EXPECT_LT(e[0], 1e-11) << "variant " << variant;
      EXPECT_LT(e[1], 1e-11) << "variant " << variant;
      EXPECT_LT(e[2], 1e-9) << "variant " << variant;
      EXPECT_LT(e[3], 1e-9) << "variant " << variant;
      const Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic> I = fd.Minv * dyn.massMatrix(s.q);
      EXPECT_LT(relErr(I, Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic>::Identity(nv, nv)), 1e-12);
    }
    std::cout << "[ measured ] scene derivatives (velocity terms " << velocity << ", contacts " << contacts << ", "
              << pushed << " pushed points) vs long double differences: dtau/dq " << worst[0] << ", dtau/dalpha "
              << worst[1] << ", dalphaD/dq " << worst[2] << ", dalphaD/dalpha " << worst[3] << "\n";
  }
}
