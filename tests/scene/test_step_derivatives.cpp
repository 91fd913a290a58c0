// Derivatives of one integrator step of a scene (rbd::scene::stepDerivatives) against long double
// central differences with one Richardson step of the runtime's own step (rbd::scene::step):
// q columns along q ⊕ t e_k (rbd::integrateConfiguration), alpha and tau columns along + t e_k, the
// outputs compared in the tangent at q⁺ (rbd::configurationDifference, tested against
// integrateConfiguration in tests/dynamics/test_integration_derivatives). Semi-implicit Euler,
// explicit Euler and RK4, on a floating-base quadruped with every non-contact effect (tilted
// gravity, velocity terms, damping, friction, armature, a locked joint, two wrenches), on
// all_joints.urdf (planar, prismatic, continuous and revolute joints, fixed base) and the quadruped
// with compliant contacts (states away from the contact boundaries, where the model has a kink).
//
// Tolerances: the long double analytic derivatives are exact to ~1e-17; the witness's error is
// truncation O(h⁴ f⁽⁵⁾) plus round-off eps |x⁺|/h (eps = 1.1e-19). RK4 at dt = 20 ms on the quadruped
// (friction a/sqrt(a² + v_s²) with v_s = 0.05 inside every stage) has a steep f⁽⁵⁾: at h = 1e-3 the
// truncation reaches 3.4e-9, at h = 1e-4 it is 3.4e-13 (a factor 1e4: truncation, not the
// derivatives). Steps: h = 1e-4 along q and tau, 1e-5 along alpha (round-off 1e-15..1e-14);
// bound 1e-11 relative to max(1, |A|), |B|. With contacts (k = 2e4 N/m, slip velocity 0.01 m/s,
// accelerations up to ~1e4: round-off grows with |alpha⁺|) h = 1e-5 along q and alpha, 1e-3 along
// tau (alpha⁺ is affine in tau for the Euler steps), bound 1e-10. The measured worst is printed.
#include <iostream>
#include <random>

#include <rbd/IntegrationDerivatives.h>
#include <rbd/scene/StepDerivatives.h>

#include "SceneTestUtils.h"

using namespace scenetest;
using LD = long double;
namespace sc = rbd::scene;

namespace
{

template<class T>
using MatX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

/// df/dt at 0: central differences with one Richardson step (error O(h^4)).
template<class F>
VecX<LD> richardson(F f, LD h)
{
  const VecX<LD> d1 = (f(h) - f(-h)) / (2 * h), d2 = (f(h / 2) - f(-h / 2)) / h;
  return VecX<LD>((4 * d2 - d1) / 3);
}

const char * kEffects = R"(  <gravity x="0.4" y="-1" z="-9.81"/>
  <joints friction_velocity="0.05">
    <joint name="FL_hip_joint" armature="0.01" damping="0.3" friction="0.2"/>
    <joint name="HR_calf_joint" armature="0.02" friction="0.5"/>
    <lock name="HL_hip_joint" position="0.1"/>
  </joints>
  <external_wrench body="trunk"/>
  <external_wrench body="FR_calf"/>)";

const char * kContacts = R"(  <joints friction_velocity="0.05">
    <joint name="FL_hip_joint" armature="0.01" damping="0.3"/>
  </joints>
  <contacts stiffness="20000" damping="300" mu="0.8" slip_velocity="0.01" ground_height="0.05">
    <point name="FL" body="FL_foot"/> <point name="FR" body="FR_foot"/>
    <point name="HL" body="HL_foot"/> <point name="HR" body="HR_foot" xyz="0.01 0 0"/>
  </contacts>)";

struct Case
{
  std::string name, xml;
  bool contacts;
  double dt;
};

std::vector<Case> cases()
{
  return {{"quadruped effects (free base)", sceneXml("quadruped.urdf", kEffects, "floating"), false, 0.02},
          {"all_joints (planar, prismatic, revolute)", sceneXml("all_joints.urdf", "<joints damping=\"urdf\"/>"), false, 0.02},
          {"quadruped contacts", sceneXml("quadruped.urdf", kContacts, "floating"), true, 1e-3}};
}

/// x⁺ of the runtime step in the tangent at ref: [ref.q ⊖ q⁺; alpha⁺].
VecX<LD> stepAt(const sc::SceneDynamicsTpl<LD> & dyn, const VecX<LD> & q, const VecX<LD> & alpha, const VecX<LD> & tau,
                LD dt, sc::Integrator integ, const sc::SceneDynamicsTpl<LD>::Wrenches & w, const VecX<LD> & qRef)
{
  sc::SceneState<LD> s{q, alpha};
  sc::step(dyn, s, tau, dt, integ, w);
  VecX<LD> x(2 * dyn.nv());
  x << rbd::configurationDifference(dyn.mb(), qRef, s.q), s.alpha;
  return x;
}

/// A state with every contact point at least 1 mm and 1 N from its boundary and at least one pushed.
bool awayFromContactBoundaries(const sc::SceneDynamicsTpl<LD> & dyn, const sc::SceneState<LD> & s)
{
  const auto p = dyn.contactPositions(s.q);
  const auto v = dyn.contactVelocities(s.q, s.alpha);
  int on = 0;
  for(std::size_t c = 0; c < p.size(); ++c)
  {
    const LD depth = 0.05L - p[c].z(), push = 2e4L * depth - 300.0L * v[c].z();
    if(std::abs(depth) < 1e-3L || (depth > 0 && std::abs(push) < 1.0L)) return false;
    on += depth > 0 && push > 0;
  }
  return on > 0;
}

} // namespace

TEST(StepDerivatives, MatchLongDoubleDifferences)
{
  std::mt19937 rng(31);
  for(const Case & c : cases())
  {
    Model<LD> m(sceneFromText(c.xml));
    const auto & dyn = m.dyn;
    const int nv = dyn.nv();
    for(sc::Integrator integ : {sc::Integrator::SemiImplicitEuler, sc::Integrator::ExplicitEuler, sc::Integrator::RK4})
    {
      double worstA = 0, worstB = 0;
      for(int trial = 0; trial < 2; ++trial)
      {
        auto s = randomState<LD>(dyn.mb(), rng);
        if(c.contacts)
        {
          s.q[6] = LD(std::uniform_real_distribution<double>(0.05, 0.3)(rng));
          if(!awayFromContactBoundaries(dyn, s))
          {
            --trial;
            continue;
          }
        }
        const auto w = [&] {
          sc::SceneDynamicsTpl<LD>::Wrenches out;
          for(std::size_t k = 0; k < m.scene.externalWrenches.size(); ++k)
            out.emplace_back(Eigen::Matrix<LD, 6, 1>(randomVector<LD>(6, rng, 5.0)));
          return out;
        }();
        const VecX<LD> tau = randomVector<LD>(nv, rng, 5.0);
        const LD dt = LD(c.dt);
        const auto d = sc::stepDerivatives(dyn, s.q, s.alpha, tau, dt, integ, w);
        // the step itself
        sc::SceneState<LD> r = s;
        sc::step(dyn, r, tau, dt, integ, w);
        EXPECT_LT(relErr(d.next.alpha, r.alpha), 1e-15) << c.name;
        EXPECT_LT(static_cast<double>(rbd::configurationDifference(dyn.mb(), r.q, d.next.q).cwiseAbs().maxCoeff()), 1e-16)
            << c.name;
        ASSERT_EQ(d.A.rows(), 2 * nv);
        ASSERT_EQ(d.A.cols(), 2 * nv);
        ASSERT_EQ(d.B.rows(), 2 * nv);
        ASSERT_EQ(d.B.cols(), nv);
        const LD hq = c.contacts ? 1e-5L : 1e-4L, ha = 1e-5L, ht = c.contacts ? 1e-3L : 1e-4L;
        MatX<LD> nA(2 * nv, 2 * nv), nB(2 * nv, nv);
        for(int k = 0; k < nv; ++k)
        {
          const VecX<LD> e = VecX<LD>::Unit(nv, k);
          nA.col(k) = richardson(
              [&](LD t) {
                return stepAt(dyn, rbd::integrateConfiguration(dyn.mb(), s.q, VecX<LD>(e * t)), s.alpha, tau, dt, integ, w, r.q);
              },
              hq);
          nA.col(nv + k) =
              richardson([&](LD t) { return stepAt(dyn, s.q, VecX<LD>(s.alpha + e * t), tau, dt, integ, w, r.q); }, ha);
          nB.col(k) = richardson([&](LD t) { return stepAt(dyn, s.q, s.alpha, VecX<LD>(tau + e * t), dt, integ, w, r.q); }, ht);
        }
        const double eA = relErr(d.A, nA), eB = relErr(d.B, nB);
        worstA = std::max(worstA, eA);
        worstB = std::max(worstB, eB);
        const double bound = c.contacts ? 1e-10 : 1e-11;
        EXPECT_LT(eA, bound) << c.name << " integrator " << static_cast<int>(integ);
        EXPECT_LT(eB, bound) << c.name << " integrator " << static_cast<int>(integ);
      }
      std::cout << "[ measured ] " << c.name << ", integrator " << static_cast<int>(integ) << ", dt " << c.dt
                << ": A " << worstA << ", B " << worstB << " vs long double differences\n";
    }
  }
}

// Structure: at dt = 0 the step is the identity (A = 1, B = 0); the double evaluation agrees with
// long double (bound: dt cond(H)-scaled FD derivative errors, 1e-12 measured well below).
TEST(StepDerivatives, IdentityAtZeroStepAndDoubleAgrees)
{
  std::mt19937 rng(32);
  for(const Case & c : cases())
  {
    if(c.contacts) continue;
    Model<LD> ml(sceneFromText(c.xml));
    Model<double> md(sceneFromText(c.xml));
    const int nv = md.dyn.nv();
    for(sc::Integrator integ : {sc::Integrator::SemiImplicitEuler, sc::Integrator::ExplicitEuler, sc::Integrator::RK4})
    {
      const auto s = randomState<LD>(ml.dyn.mb(), rng);
      const VecX<LD> tau = randomVector<LD>(nv, rng, 5.0);
      sc::SceneDynamicsTpl<LD>::Wrenches wl;
      sc::SceneDynamics::Wrenches wd;
      for(std::size_t k = 0; k < ml.scene.externalWrenches.size(); ++k)
      {
        const Eigen::Matrix<LD, 6, 1> v = randomVector<LD>(6, rng, 5.0);
        wl.emplace_back(v);
        wd.emplace_back(Eigen::Matrix<double, 6, 1>(v.cast<double>()));
      }
      const auto d0 = sc::stepDerivatives(md.dyn, Eigen::VectorXd(s.q.cast<double>()), Eigen::VectorXd(s.alpha.cast<double>()),
                                          Eigen::VectorXd(tau.cast<double>()), 0.0, integ, wd);
      EXPECT_LT(relErr(d0.A, Eigen::MatrixXd::Identity(2 * nv, 2 * nv)), 1e-15);
      EXPECT_EQ(d0.B.cwiseAbs().maxCoeff(), 0.0);
      const auto dl = sc::stepDerivatives(ml.dyn, s.q, s.alpha, tau, LD(c.dt), integ, wl);
      const auto dd = sc::stepDerivatives(md.dyn, Eigen::VectorXd(s.q.cast<double>()), Eigen::VectorXd(s.alpha.cast<double>()),
                                          Eigen::VectorXd(tau.cast<double>()), c.dt, integ, wd);
      const double eA = relErr(Eigen::MatrixXd(dl.A.cast<double>()), dd.A), eB = relErr(Eigen::MatrixXd(dl.B.cast<double>()), dd.B);
      EXPECT_LT(eA, 1e-12) << c.name;
      EXPECT_LT(eB, 1e-12) << c.name;
      std::cout << "[ measured ] " << c.name << ", integrator " << static_cast<int>(integ) << ": double vs long double A "
                << eA << ", B " << eB << "\n";
    }
  }
}
