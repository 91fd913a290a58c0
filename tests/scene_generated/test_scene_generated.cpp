// Every scene-specialised generated header against the runtime's generic evaluation of the same
// scene file (rbd::scene::SceneDynamics, rbd::scene::step) on seeded random states: double within
// 1e-12, error = max |generated - runtime| / max(1, max |runtime|). A function the scene leaves out
// must be absent exactly when the scene disables its effect.
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <rbd/EulerIntegration.h>
#include <rbd/FK.h>
#include <rbd/FV.h>
#include <rbd/ID.h>
#include <rbd/scene/Integrators.h>
#include <rbd/scene/SceneDynamics.h>
#include <rbd/scene/StepDerivatives.h>

#include "../generator/AllocationCounter.h"
#include "SceneAdapter.h"
#include "TestModels.h"

namespace scenegentest
{
const std::vector<const SceneAdapter *> & sceneAdapters();
} // namespace scenegentest

namespace
{
using scenegentest::SceneAdapter;
using Vec = Eigen::VectorXd;
namespace sc = rbd::scene;

constexpr double kTol = 1e-12;
constexpr int kStates = 50;

template<class A, class B>
double err(const Eigen::MatrixBase<A> & a, const Eigen::MatrixBase<B> & b)
{
  return rbdtest::relErr(a, b);
}

/// Worst error of one function over the states, printed at the end.
struct Log
{
  std::string what;
  double worst = 0;
  int n = 0;
  void add(double e)
  {
    worst = std::max(worst, e);
    ++n;
  }
  ~Log()
  {
    if(n) std::printf("[ %-28s ] worst relative error %.3g over %d evaluations\n", what.c_str(), worst, n);
  }
};

struct Reference
{
  sc::Scene scene;
  sc::SceneRobot robot;
  sc::SceneDynamics dyn;
  explicit Reference(const SceneAdapter & g)
  : scene(sc::loadScene(g.sceneFile)), robot(sc::loadSceneRobot(scene)), dyn(robot, scene)
  {
  }
};

/// A random state (unit quaternions); with contacts, the free root's height is moved so that the
/// lowest contact point sits between 3 cm below and 1 cm above the ground (some points in contact,
/// some not).
struct State
{
  Vec q, alpha, alphaD, tau, w;
};

State randomState(rbdtest::Rng & rng, const Reference & ref, const SceneAdapter & g)
{
  const rbd::MultiBody & mb = ref.robot.robot.mb;
  rbd::MultiBodyConfig mbc(mb);
  rbdtest::randomState(rng, mb, mbc, 1.5, 2.0);
  State s{rbd::paramToVector(mb, mbc.q), rbd::dofToVector(mb, mbc.alpha), rbd::dofToVector(mb, mbc.alphaD),
          rbd::dofToVector(mb, mbc.jointTorque), Vec(6 * g.nwrenches)};
  for(Eigen::Index i = 0; i < s.w.size(); ++i) s.w[i] = rbdtest::uniform(rng, -10, 10);
  if(g.ncontacts > 0 && mb.joint(0).type() == rbd::Joint::Free)
  {
    double lowest = 1e9;
    for(const auto & p : ref.dyn.contactPositions(s.q)) lowest = std::min(lowest, p.z());
    s.q[6] += ref.scene.contactModel.groundHeight - lowest + rbdtest::uniform(rng, -0.03, 0.01);
  }
  return s;
}

sc::SceneDynamics::Wrenches toWrenches(const Vec & w)
{
  sc::SceneDynamics::Wrenches out;
  for(Eigen::Index i = 0; i + 6 <= w.size(); i += 6) out.emplace_back(Eigen::Matrix<double, 6, 1>(w.segment<6>(i)));
  return out;
}

/// Runtime RNEA with selected terms (gravity: the scene's or none; velocity: alpha or 0).
Vec runtimeRnea(const Reference & ref, const State & s, bool velocity, bool gravity)
{
  const rbd::MultiBody & mb = ref.robot.robot.mb;
  rbd::MultiBodyConfig mbc(mb);
  mbc.q = rbd::vectorToParam(mb, s.q);
  mbc.alpha = rbd::vectorToDof(mb, velocity ? s.alpha : Vec(Vec::Zero(mb.nrDof())));
  mbc.alphaD = rbd::vectorToDof(mb, Vec(Vec::Zero(mb.nrDof())));
  mbc.gravity = gravity ? Eigen::Vector3d(-ref.dyn.gravity()) : Eigen::Vector3d::Zero();
  rbd::forwardKinematics(mb, mbc);
  rbd::forwardVelocity(mb, mbc);
  rbd::InverseDynamics id(mb);
  id.inverseDynamics(mb, mbc);
  return rbd::dofToVector(mb, mbc.jointTorque);
}

class SceneGenerated : public ::testing::TestWithParam<const SceneAdapter *>
{
protected:
  const SceneAdapter & g() const { return *GetParam(); }
};

TEST_P(SceneGenerated, PresenceMatchesTheScene)
{
  Reference ref(g());
  const sc::Scene & s = ref.scene;
  ASSERT_EQ(g().nq, ref.dyn.nq());
  ASSERT_EQ(g().nv, ref.dyn.nv());
  EXPECT_EQ(g().nwrenches, static_cast<int>(s.externalWrenches.size()));
  EXPECT_EQ(g().ncontacts, static_cast<int>(s.contacts.size()));
  const bool gravity = s.gravity && !s.gravity->isZero();
  EXPECT_EQ(g().gravityTorques != nullptr, gravity);
  EXPECT_EQ(g().velocityTorques != nullptr, s.velocityTerms);
  EXPECT_EQ(g().contactForces != nullptr, !s.contacts.empty());
  EXPECT_EQ(g().centerOfMass != nullptr, s.outputs.com);
  EXPECT_EQ(g().centroidalMomentum != nullptr, s.outputs.momentum);
  EXPECT_EQ(g().energy != nullptr, s.outputs.energy);
  EXPECT_EQ(g().inverseDynamicsDerivatives != nullptr, s.outputs.derivatives);
  EXPECT_EQ(g().nposes, static_cast<int>(s.outputs.poses.size()));
  EXPECT_EQ(g().njacobians, static_cast<int>(s.outputs.jacobians.size()));
  // has_forward_dynamics exactly where the runtime's H + diag(armature) is regular (rank-revealing).
  rbdtest::Rng rng(11);
  bool regular = true;
  for(int k = 0; k < 20; ++k)
  {
    const State st = randomState(rng, ref, g());
    const Eigen::MatrixXd H = ref.dyn.massMatrix(st.q);
    regular = regular && Eigen::FullPivLU<Eigen::MatrixXd>(H).rank() == H.rows();
  }
  EXPECT_EQ(g().hasForwardDynamics, regular);
  EXPECT_EQ(g().forwardDynamics != nullptr, regular);
  EXPECT_EQ(g().step != nullptr, regular);
  EXPECT_TRUE(g().floatFinite()) << "a float function returned NaN or Inf";
}

TEST_P(SceneGenerated, Dynamics)
{
  Reference ref(g());
  rbdtest::Rng rng(1);
  const int nv = g().nv;
  Log lH{"mass_matrix"}, lHp{"mass_matrix_packed"}, lID{"inverse_dynamics"}, lFD{"forward_dynamics"}, lB{"generalized_bias"},
      lG{"gravity_torques"}, lV{"velocity_torques"}, lN{"nonlinear_effects"}, lC{"contact_forces"};
  Eigen::MatrixXd H(nv, nv);
  Vec out(nv);
  int active = 0;
  for(int k = 0; k < kStates; ++k)
  {
    const State s = randomState(rng, ref, g());
    const auto W = toWrenches(s.w);
    g().massMatrix(s.q.data(), H.data());
    lH.add(err(H, ref.dyn.massMatrix(s.q)));
    g().massMatrixPacked(s.q.data(), H.data());
    lHp.add(err(H, ref.dyn.massMatrix(s.q)));
    g().inverseDynamics(s.q.data(), s.alpha.data(), s.alphaD.data(), s.w.data(), out.data());
    lID.add(err(out, ref.dyn.inverseDynamics(s.q, s.alpha, s.alphaD, W)));
    if(g().generalizedBias)
    {
      g().generalizedBias(s.q.data(), s.alpha.data(), s.w.data(), out.data());
      lB.add(err(out, ref.dyn.generalizedBias(s.q, s.alpha, W)));
    }
    if(g().forwardDynamics)
    {
      g().forwardDynamics(s.q.data(), s.alpha.data(), s.tau.data(), s.w.data(), out.data());
      lFD.add(err(out, ref.dyn.forwardDynamics(s.q, s.alpha, s.tau, W)));
    }
    if(g().gravityTorques)
    {
      g().gravityTorques(s.q.data(), out.data());
      lG.add(err(out, runtimeRnea(ref, s, false, true)));
    }
    if(g().velocityTorques)
    {
      g().velocityTorques(s.q.data(), s.alpha.data(), out.data());
      lV.add(err(out, runtimeRnea(ref, s, true, false)));
    }
    if(g().nonlinearEffects)
    {
      g().nonlinearEffects(s.q.data(), s.alpha.data(), out.data());
      lN.add(err(out, runtimeRnea(ref, s, ref.scene.velocityTerms, g().gravityTorques != nullptr)));
    }
    if(g().contactForces)
    {
      Vec fc(3 * g().ncontacts), fr(3 * g().ncontacts);
      g().contactForces(s.q.data(), s.alpha.data(), fc.data());
      const auto ref_f = ref.dyn.contactForces(s.q, s.alpha);
      for(int c = 0; c < g().ncontacts; ++c)
      {
        fr.segment<3>(3 * c) = ref_f[static_cast<std::size_t>(c)];
        active += ref_f[static_cast<std::size_t>(c)].z() > 0;
      }
      lC.add(err(fc, fr));
    }
  }
  if(g().contactForces)
  {
    std::printf("[ %-28s ] %d active contact evaluations of %d\n", "contacts", active, kStates * g().ncontacts);
    // Enough evaluations with the point in the ground (a non-zero force to compare): at least 10.
    EXPECT_GE(active, 10) << "the random states must put contacts in the ground";
    EXPECT_LT(active, kStates * g().ncontacts) << "and some out of it";
  }
  for(const Log * l : {&lH, &lHp, &lID, &lFD, &lB, &lG, &lV, &lN, &lC})
  {
    EXPECT_LE(l->worst, kTol) << l->what;
  }
  EXPECT_EQ(lFD.n, g().forwardDynamics ? kStates : 0);
}

// Derivatives of the scene's dynamics against the runtime's (SceneDynamics: the runtime's analytic
// derivatives plus the joint terms; tested against long double differences in tests/scene).
TEST_P(SceneGenerated, Derivatives)
{
  Reference ref(g());
  if(!ref.scene.outputs.derivatives)
  {
    EXPECT_EQ(g().inverseDynamicsDerivatives, nullptr);
    EXPECT_EQ(g().forwardDynamicsDerivatives, nullptr);
    return;
  }
  rbdtest::Rng rng(5);
  const int nv = g().nv;
  Log lq{"dtau_dq"}, la{"dtau_dalpha"}, lfq{"dalphaD_dq"}, lfa{"dalphaD_dalpha"}, lmi{"Minv"}, lad{"fd_derivatives alphaD"};
  Eigen::MatrixXd dq(nv, nv), da(nv, nv), fq(nv, nv), fa(nv, nv), mi(nv, nv);
  Vec ad(nv);
  int pushed = 0; // contact points with a force (their derivatives are not zero)
  for(int k = 0; k < kStates; ++k)
  {
    const State s = randomState(rng, ref, g());
    const auto W = toWrenches(s.w);
    for(const auto & f : ref.dyn.contactForces(s.q, s.alpha)) pushed += f.z() > 0;
    const auto r = ref.dyn.inverseDynamicsDerivatives(s.q, s.alpha, s.alphaD, W);
    g().inverseDynamicsDerivatives(s.q.data(), s.alpha.data(), s.alphaD.data(), s.w.data(), dq.data(), da.data());
    lq.add(err(dq, r.dtauDq));
    la.add(err(da, r.dtauDalpha));
    if(!g().forwardDynamicsDerivatives) continue;
    const auto f = ref.dyn.forwardDynamicsDerivatives(s.q, s.alpha, s.tau, W);
    g().forwardDynamicsDerivatives(s.q.data(), s.alpha.data(), s.tau.data(), s.w.data(), ad.data(), fq.data(), fa.data(),
                                   mi.data());
    lad.add(err(ad, f.alphaD));
    lmi.add(err(mi, f.Minv));
    lfq.add(err(fq, f.dalphaDDq));
    lfa.add(err(fa, f.dalphaDDalpha));
  }
  for(const Log * l : {&lq, &la, &lad, &lmi}) EXPECT_LE(l->worst, kTol) << l->what;
  // -M^-1 dID: two solvers (LLT vs tree-sparse LTDL) differ by ~cond(M) eps times |dID|
  for(const Log * l : {&lfq, &lfa}) EXPECT_LE(l->worst, 100 * kTol) << l->what;
  EXPECT_EQ(lfq.n, g().forwardDynamicsDerivatives ? kStates : 0);
  if(g().ncontacts > 0)
  {
    EXPECT_GT(pushed, kStates / 4) << "too few states with contact forces to test their derivatives";
  }
}

TEST_P(SceneGenerated, Outputs)
{
  Reference ref(g());
  rbdtest::Rng rng(2);
  Log lP{"pose_<link>"}, lJ{"jacobian_<link>"}, lC{"center_of_mass"}, lM{"centroidal_momentum"}, lK{"kinetic_energy"},
      lU{"potential_energy"}, lE{"energy"};
  for(int k = 0; k < kStates; ++k)
  {
    const State s = randomState(rng, ref, g());
    for(int i = 0; i < g().nposes; ++i)
    {
      Eigen::Matrix<double, 12, 1> p, e;
      g().pose(i, s.q.data(), p.data());
      const sva::PTransformd X = ref.dyn.pose(s.q, g().poseLinks[i]);
      for(int r = 0; r < 3; ++r)
        for(int c = 0; c < 3; ++c) e[3 * r + c] = X.rotation()(r, c);
      e.tail<3>() = X.translation();
      lP.add(err(p, e));
    }
    for(int i = 0; i < g().njacobians; ++i)
    {
      Eigen::MatrixXd J(6, g().nv);
      g().jacobian(i, s.q.data(), J.data());
      lJ.add(err(J, ref.dyn.jacobian(s.q, g().jacobianLinks[i])));
    }
    if(g().centerOfMass)
    {
      Eigen::Vector3d c;
      g().centerOfMass(s.q.data(), c.data());
      lC.add(err(c, ref.dyn.centerOfMass(s.q)));
    }
    if(g().centroidalMomentum)
    {
      Eigen::Matrix<double, 6, 1> h;
      g().centroidalMomentum(s.q.data(), s.alpha.data(), h.data());
      lM.add(err(h, ref.dyn.centroidalMomentum(s.q, s.alpha).vector()));
    }
    if(g().energy)
    {
      Eigen::Matrix<double, 1, 1> ek, e, ekr, er;
      g().kineticEnergy(s.q.data(), s.alpha.data(), ek.data());
      g().energy(s.q.data(), s.alpha.data(), e.data());
      ekr[0] = ref.dyn.kineticEnergy(s.q, s.alpha);
      er[0] = ekr[0] + ref.dyn.potentialEnergy(s.q);
      lK.add(err(ek, ekr));
      lE.add(err(e, er));
      if(g().potentialEnergy)
      {
        Eigen::Matrix<double, 1, 1> u, ur;
        g().potentialEnergy(s.q.data(), u.data());
        ur[0] = ref.dyn.potentialEnergy(s.q);
        lU.add(err(u, ur));
      }
    }
  }
  for(const Log * l : {&lP, &lJ, &lC, &lM, &lK, &lU, &lE})
  {
    EXPECT_LE(l->worst, kTol) << l->what;
  }
}

// Scenes with forward dynamics only (PresenceMatchesTheScene proves which scenes must lack step()).
class SceneGeneratedStep : public SceneGenerated
{
};

TEST_P(SceneGeneratedStep, StepAndIntegration)
{
  ASSERT_NE(g().step, nullptr);
  Reference ref(g());
  rbdtest::Rng rng(3);
  // Stiff contacts from random leg states diverge at dt = 1 ms in both implementations (omega dt > 2
  // for a light foot on k = 2e4 N/m): with contacts the steps are 0.1 ms.
  const double dt = g().ncontacts > 0 ? std::min(ref.scene.dt, 1e-4) : ref.scene.dt;
  Log l1{"step x1"}, l100{"step x100"}, lI{"integrate"}, l0{"initial_state"};
  {
    Vec q(g().nq), a(g().nv);
    g().initialState(q.data(), a.data());
    const sc::SceneState<double> s0 = sc::initialState(ref.dyn);
    Vec both(q.size() + a.size()), both0(q.size() + a.size());
    both << q, a;
    both0 << s0.q, s0.alpha;
    l0.add(err(both, both0));
  }
  for(int k = 0; k < 10; ++k)
  {
    const State s = randomState(rng, ref, g());
    const auto W = toWrenches(s.w);
    // q (+) dq
    Vec qi(g().nq);
    const Vec dq = 0.3 * s.alphaD;
    g().integrate(s.q.data(), dq.data(), qi.data());
    lI.add(err(qi, rbd::integrateConfiguration(ref.robot.robot.mb, s.q, dq)));
    for(int steps : {1, 100})
    {
      Vec q = s.q, a = s.alpha;
      sc::SceneState<double> r{s.q, s.alpha};
      for(int n = 0; n < steps; ++n)
      {
        g().step(q.data(), a.data(), s.tau.data(), dt, s.w.data());
        sc::step(ref.dyn, r, s.tau, dt, ref.scene.integrator, W);
      }
      Vec x(q.size() + a.size()), xr(q.size() + a.size());
      x << q, a;
      xr << r.q, r.alpha;
      (steps == 1 ? l1 : l100).add(err(x, xr));
    }
  }
  for(const Log * l : {&l0, &lI, &l1, &l100})
  {
    EXPECT_LE(l->worst, kTol) << l->what;
  }
}

// step_derivatives against the runtime's rbd::scene::stepDerivatives (itself tested against long
// double differences of the runtime step in tests/scene/test_step_derivatives) at the scene's dt
// and at 20 ms (rotations of a few degrees per step: the per-joint derivative blocks of q (+) w far
// from the identity). The stepped state: 1e-12 like step(). A and B: their alpha rows are dt times
// the forward dynamics derivatives, which two solvers give ~cond(M) eps apart (the Derivatives test
// above bounds them by 1e-10 relative to max(1, |d alphaD|)); dt X relative to max(1, |A|) is then
// within the same 1e-10, and the integration blocks (a few ulps apart) add nothing visible: bound
// 1e-10 (measured worst 9.5e-13, arm_gravity at 20 ms). Scenes with contacts take 0.1 ms steps.
TEST_P(SceneGenerated, StepDerivatives)
{
  Reference ref(g());
  if(!ref.scene.outputs.derivatives || !g().forwardDynamics)
  {
    EXPECT_EQ(g().stepDerivatives, nullptr);
    return;
  }
  ASSERT_NE(g().stepDerivatives, nullptr);
  rbdtest::Rng rng(6);
  const int nq = g().nq, nv = g().nv;
  Log lA{"step_derivatives A"}, lB{"step_derivatives B"}, lx{"step_derivatives x+"};
  const std::vector<double> dts =
      g().ncontacts > 0 ? std::vector<double>{std::min(ref.scene.dt, 1e-4)} : std::vector<double>{ref.scene.dt, 0.02};
  for(double dt : dts)
    for(int k = 0; k < 20; ++k)
    {
      const State s = randomState(rng, ref, g());
      const auto W = toWrenches(s.w);
      rbdgentest::AllocationScope live; // the counter works here: the runtime allocates
      const sc::StepDerivatives r = sc::stepDerivatives(ref.dyn, s.q, s.alpha, s.tau, dt, ref.scene.integrator, W);
      EXPECT_GT(live.count(), 0);
      Vec qn(nq), an(nv);
      Eigen::MatrixXd A(2 * nv, 2 * nv), B(2 * nv, nv);
      {
        rbdgentest::AllocationScope heap; // fixed-size Eigen only: no heap allocation
        g().stepDerivatives(s.q.data(), s.alpha.data(), s.tau.data(), dt, s.w.data(), qn.data(), an.data(), A.data(), B.data());
        EXPECT_EQ(heap.count(), 0) << "step_derivatives allocated";
      }
      Vec x(nq + nv), xr(nq + nv);
      x << qn, an;
      xr << r.next.q, r.next.alpha;
      lx.add(err(x, xr));
      lA.add(err(A, r.A));
      lB.add(err(B, r.B));
    }
  EXPECT_LE(lx.worst, kTol) << lx.what;
  for(const Log * l : {&lA, &lB}) EXPECT_LE(l->worst, 100 * kTol) << l->what;
}

std::string adapterName(const ::testing::TestParamInfo<const SceneAdapter *> & info)
{
  return info.param->name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneGenerated, ::testing::ValuesIn(scenegentest::sceneAdapters()), adapterName);

std::vector<const SceneAdapter *> scenesWithStep()
{
  std::vector<const SceneAdapter *> out;
  for(const SceneAdapter * a : scenegentest::sceneAdapters())
    if(a->step) out.push_back(a);
  return out;
}
INSTANTIATE_TEST_SUITE_P(Scenes, SceneGeneratedStep, ::testing::ValuesIn(scenesWithStep()), adapterName);

} // namespace
