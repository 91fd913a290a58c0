// A scene whose robot has mimic joints (scenes/mimic_gripper.xml): its API in the coupled
// coordinates (namespace sg_mimic_gripper) against computations made here from the full model
// (sg_mimic_gripper::independent, compared with the runtime scene by test_scene_generated), a
// coupling matrix built here from the URDF's <mimic> elements (q_full = Gq q + o, alpha_full = Gv alpha)
// and the runtime's configuration maps:
//   - every torque-like function = Gv^T (full function at the expanded state), H = Gv^T H_full Gv,
//     Jacobians J_full Gv, poses, contact forces, CoM, momentum and potential energy those of the full
//     model, kinetic energy alpha^T H alpha / 2 with the coupled H;
//   - forward dynamics = Eigen's LDLT solve of the coupled equations, and inverse dynamics inverts it;
//   - step() = an RK4 step written here (coupled accelerations as above, dq/dt from the runtime's
//     rbd::configurationDerivative of the full model);
//   - derivatives of inverse and forward dynamics and of step() against long double central
//     differences (one Richardson step) of the header's own functions, perturbing q along the coupled
//     tangent through the runtime's rbd::integrateConfiguration of the full model (q (+) t Gv e_k).
// Tolerances: projections and solves agree to round-off (1e-12 relative to max(1, |reference|));
// the derivative witnesses' truncation is O(h^4) = 1e-16 (h = 1e-4) and round-off eps_LD / h = 1e-15,
// so the bound 1e-9 relative measures the double analytic derivatives (worst printed). The
// derivative states hold the base high above the ground: the compliant contact has a kink at the
// contact boundary (the contact forces themselves are checked at states with contacts).
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <rbd/EulerIntegration.h>
#include <rbd/IntegrationDerivatives.h>
#include <rbd/scene/SceneDynamics.h>
#include <rbd/scene/SceneLoader.h>

#include <sg_mimic_gripper/dynamics.hpp>

#include "MimicCouplingMatrix.h"

namespace
{

namespace ns = sg_mimic_gripper;
namespace full = sg_mimic_gripper::independent;
using LD = long double;
template<class T>
using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
template<class T>
using MatX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

/// max |a - b| / max(1, max |b|)
template<class A, class B>
double relErr(const A & a, const B & b)
{
  const double scale = std::max(1.0, static_cast<double>(b.cwiseAbs().maxCoeff()));
  return static_cast<double>((a - b).cwiseAbs().maxCoeff()) / scale;
}

struct MimicScene
{
  rbd::scene::Scene scene = rbd::scene::loadScene(SG_MIMIC_SCENE);
  rbd::scene::SceneRobot sr = rbd::scene::loadSceneRobot(scene);
  rbdgentest::Coupling c = rbdgentest::coupling(sr.robot);
  rbd::scene::SceneDynamicsTpl<LD> dynLD{sr, scene};

  /// q_full = Gq q + o
  VecX<double> expand(const VecX<double> & q) const { return c.Gq * q + c.o; }
  /// The coupled coordinates of a full configuration (each kept joint's own).
  template<class T>
  VecX<T> select(const VecX<T> & qf) const
  {
    VecX<T> q(static_cast<Eigen::Index>(c.own.size()));
    for(std::size_t k = 0; k < c.own.size(); ++k) q[static_cast<Eigen::Index>(k)] = qf[c.own[k]];
    return q;
  }
  /// The coupled components of a full tangent vector whose mimic components follow their sources.
  template<class T>
  VecX<T> selectTangent(const VecX<T> & vf) const
  {
    VecX<T> v(static_cast<Eigen::Index>(c.ownV.size()));
    for(std::size_t k = 0; k < c.ownV.size(); ++k) v[static_cast<Eigen::Index>(k)] = vf[c.ownV[k]];
    return v;
  }
  /// q (+) t e_k in the coupled tangent: the full configuration moved along Gv e_k (runtime).
  VecX<LD> perturb(const VecX<LD> & q, int k, LD t) const
  {
    const VecX<LD> qf = c.Gq.cast<LD>() * q + c.o.cast<LD>();
    return select<LD>(rbd::integrateConfiguration(dynLD.mb(), qf, VecX<LD>(c.Gv.cast<LD>().col(k) * t)));
  }
  /// A random coupled state: unit base quaternion, base height in [zLow, zHigh].
  void randomState(std::mt19937 & rng, VecX<double> & q, VecX<double> & alpha, double zLow, double zHigh) const
  {
    std::uniform_real_distribution<double> u(-1, 1), z(zLow, zHigh);
    q = VecX<double>::NullaryExpr(ns::nq, [&] { return u(rng); });
    q.head<4>().normalize();
    q[6] = z(rng);
    alpha = VecX<double>::NullaryExpr(ns::nv, [&] { return u(rng); });
  }
};

const MimicScene & scene()
{
  static const MimicScene m;
  return m;
}

ns::Wrenches<double> randomWrenches(std::mt19937 & rng)
{
  std::uniform_real_distribution<double> u(-2, 2);
  ns::Wrenches<double> w;
  for(auto & x : w) x = ns::Wrench<double>::NullaryExpr([&] { return u(rng); });
  return w;
}

template<class T>
ns::Wrenches<T> cast(const ns::Wrenches<double> & w)
{
  ns::Wrenches<T> r;
  for(std::size_t i = 0; i < w.size(); ++i) r[i] = w[i].cast<T>();
  return r;
}

/// The coupled accelerations computed here: (Gv^T H_full Gv) a = tau - Gv^T b_full (Eigen LDLT).
VecX<double> coupledAccelerations(const VecX<double> & q, const VecX<double> & alpha, const VecX<double> & tau,
                                  const ns::Wrenches<double> & w)
{
  const MimicScene & s = scene();
  const MatX<double> & G = s.c.Gv;
  const full::Config<double> qf = s.expand(q);
  const full::Tangent<double> af = G * alpha;
  const MatX<double> H = G.transpose() * full::mass_matrix<double>(qf) * G;
  return H.ldlt().solve(tau - G.transpose() * full::generalized_bias<double>(qf, af, w));
}

/// df/dt at 0: central differences with one Richardson step (error O(h^4)).
template<class F>
VecX<LD> richardson(F f, LD h)
{
  const VecX<LD> d1 = (f(h) - f(-h)) / (2 * h), d2 = (f(h / 2) - f(-h / 2)) / h;
  return VecX<LD>((4 * d2 - d1) / 3);
}

TEST(SceneMimic, CoupledCoordinatesFollowTheUrdf)
{
  const MimicScene & s = scene();
  ASSERT_EQ(ns::nq, s.c.Gq.cols());
  ASSERT_EQ(ns::nv, s.c.Gv.cols());
  ASSERT_EQ(full::nq, s.c.Gq.rows());
  EXPECT_EQ(static_cast<int>(ns::mimic_couplings.size()), s.c.mimics);
  EXPECT_GE(s.c.mimics, 4); // the pair, the chain, across subtrees, prismatic -> revolute
  for(int k = 0; k < ns::nv; ++k) EXPECT_STREQ(ns::dof_names[k], full::dof_names[s.c.ownV[k]]);
  std::mt19937 rng(7);
  for(int trial = 0; trial < 5; ++trial)
  {
    VecX<double> q, alpha;
    s.randomState(rng, q, alpha, -0.5, 0.5);
    EXPECT_LT(relErr(VecX<double>(ns::expand_configuration<double>(q)), s.expand(q)), 1e-15);
    EXPECT_LT(relErr(VecX<double>(ns::expand_tangent<double>(alpha)), VecX<double>(s.c.Gv * alpha)), 1e-15);
  }
  // The scene's initial state, on the coupled coordinates.
  const ns::State<double> s0 = ns::initial_state<double>();
  const full::State<double> f0 = full::initial_state<double>();
  EXPECT_EQ(VecX<double>(s0.q), s.select<double>(f0.q));
  EXPECT_EQ(VecX<double>(s0.alpha), s.selectTangent<double>(f0.alpha));
}

TEST(SceneMimic, EveryFunctionIsTheFullModelProjected)
{
  const MimicScene & s = scene();
  const MatX<double> & G = s.c.Gv;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int withContact = 0;
  for(int trial = 0; trial < 20; ++trial)
  {
    VecX<double> q, alpha;
    s.randomState(rng, q, alpha, -0.5, 0.2); // some states with contact against z = -0.3
    const VecX<double> alphaD = VecX<double>::NullaryExpr(ns::nv, [&] { return u(rng); });
    const ns::Wrenches<double> w = randomWrenches(rng);
    const full::Config<double> qf = s.expand(q);
    const full::Tangent<double> af = G * alpha, adf = G * alphaD;
    const MatX<double> H = G.transpose() * full::mass_matrix<double>(qf) * G;
    EXPECT_LT(relErr(ns::mass_matrix<double>(q), H), 1e-13);
    {
      // the packed lower triangle (every entry with coupled mimic joints), both triangles
      MatX<double> Hp = MatX<double>::Zero(ns::nv, ns::nv);
      const auto packed = ns::mass_matrix_packed<double>(q);
      for(std::size_t k = 0; k < packed.size(); ++k)
        Hp(ns::mass_matrix_entries[k].row, ns::mass_matrix_entries[k].col) =
            Hp(ns::mass_matrix_entries[k].col, ns::mass_matrix_entries[k].row) = packed[k];
      EXPECT_LT(relErr(Hp, H), 1e-13);
    }
    EXPECT_LT(relErr(ns::gravity_torques<double>(q), G.transpose() * full::gravity_torques<double>(qf)), 1e-13);
    EXPECT_LT(relErr(ns::velocity_torques<double>(q, alpha), G.transpose() * full::velocity_torques<double>(qf, af)), 1e-13);
    EXPECT_LT(relErr(ns::nonlinear_effects<double>(q, alpha), G.transpose() * full::nonlinear_effects<double>(qf, af)), 1e-13);
    EXPECT_LT(relErr(ns::inverse_dynamics<double>(q, alpha, alphaD, w),
                     G.transpose() * full::inverse_dynamics<double>(qf, af, adf, w)),
              1e-13);
    EXPECT_LT(relErr(ns::generalized_bias<double>(q, alpha, w), G.transpose() * full::generalized_bias<double>(qf, af, w)),
              1e-13);
    const auto fc = ns::contact_forces<double>(q, alpha), ffc = full::contact_forces<double>(qf, af);
    for(std::size_t k = 0; k < fc.size(); ++k)
    {
      EXPECT_LT(relErr(fc[k], ffc[k]), 1e-13);
      withContact += ffc[k].norm() > 0;
    }
    EXPECT_LT(relErr(ns::pose_camera<double>(q).rotation, full::pose_camera<double>(qf).rotation), 1e-14);
    EXPECT_LT(relErr(ns::pose_knuckle<double>(q).translation, full::pose_knuckle<double>(qf).translation), 1e-14);
    EXPECT_LT(relErr(ns::jacobian_flap<double>(q), full::jacobian_flap<double>(qf) * G), 1e-13);
    // <kinematics/>: every link's pose and the support-path Jacobian, against the outputs above (other
    // emitted code: one link's pose, one link's Jacobian), and the Jacobian at a point of the link
    // (v_p = v + w x (R p), R = the link's axes in world)
    const auto poses = ns::forward_kinematics<double>(q);
    EXPECT_LT(relErr(poses[static_cast<std::size_t>(ns::Body::camera)].rotation, full::pose_camera<double>(qf).rotation), 1e-14);
    EXPECT_LT(relErr(poses[static_cast<std::size_t>(ns::Body::knuckle)].translation, full::pose_knuckle<double>(qf).translation),
              1e-14);
    const MatX<double> Jflap = full::jacobian_flap<double>(qf) * G;
    EXPECT_LT(relErr(ns::jacobian<double>(ns::Body::flap, q), Jflap), 1e-13);
    const Eigen::Vector3d p(0.03, -0.02, 0.05);
    const Eigen::Vector3d Rp = full::forward_kinematics<double>(qf)[static_cast<std::size_t>(ns::Body::flap)].rotation.transpose() * p;
    MatX<double> Jp = Jflap;
    for(int c = 0; c < ns::nv; ++c) Jp.block<3, 1>(3, c) += Jflap.block<3, 1>(0, c).cross(Rp);
    EXPECT_LT(relErr(ns::jacobian<double>(ns::Body::flap, q, p), Jp), 1e-13);
    EXPECT_LT(relErr(ns::center_of_mass<double>(q), full::center_of_mass<double>(qf)), 1e-14);
    EXPECT_LT(relErr(ns::centroidal_momentum<double>(q, alpha), full::centroidal_momentum<double>(qf, af)), 1e-13);
    // kinetic energy alpha^T H alpha / 2 with the coupled H (armature included in both)
    EXPECT_NEAR(ns::kinetic_energy<double>(q, alpha), 0.5 * alpha.dot(H * alpha), 1e-12 * (1 + alpha.dot(H * alpha)));
    EXPECT_NEAR(ns::potential_energy<double>(q), full::potential_energy<double>(qf), 1e-12);
    EXPECT_NEAR(ns::energy<double>(q, alpha), ns::kinetic_energy<double>(q, alpha) + ns::potential_energy<double>(q), 1e-12);
  }
  EXPECT_GT(withContact, 0) << "no state touched the ground: contact forces were not compared";
}

TEST(SceneMimic, ForwardDynamicsSolvesTheCoupledEquations)
{
  const MimicScene & s = scene();
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-3, 3);
  for(int trial = 0; trial < 20; ++trial)
  {
    VecX<double> q, alpha;
    s.randomState(rng, q, alpha, -0.5, 0.2);
    const VecX<double> tau = VecX<double>::NullaryExpr(ns::nv, [&] { return u(rng); });
    const ns::Wrenches<double> w = randomWrenches(rng);
    const VecX<double> a = ns::forward_dynamics<double>(q, alpha, tau, w);
    const VecX<double> ref = coupledAccelerations(q, alpha, tau, w);
    EXPECT_LT(relErr(a, ref), 1e-10) << "trial " << trial;
    EXPECT_LT(relErr(VecX<double>(ns::inverse_dynamics<double>(q, alpha, a, w)), tau), 1e-10) << "trial " << trial;
  }
}

TEST(SceneMimic, StepIsRk4OfTheCoupledDynamics)
{
  const MimicScene & s = scene();
  const rbd::MultiBody & mb = s.sr.robot.mb;
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-3, 3);
  const double dt = 1e-3;
  for(int trial = 0; trial < 5; ++trial)
  {
    VecX<double> q, alpha;
    s.randomState(rng, q, alpha, -0.5, 0.2);
    const VecX<double> tau = VecX<double>::NullaryExpr(ns::nv, [&] { return u(rng); });
    const ns::Wrenches<double> w = randomWrenches(rng);
    // classical RK4 on (q, alpha), q in R^nq: dq/dt of the full model on the coupled coordinates
    auto qdot = [&](const VecX<double> & qs, const VecX<double> & as) {
      return s.select<double>(rbd::configurationDerivative(mb, s.expand(qs), VecX<double>(s.c.Gv * as)));
    };
    auto adot = [&](const VecX<double> & qs, const VecX<double> & as) { return coupledAccelerations(qs, as, tau, w); };
    const VecX<double> q1 = qdot(q, alpha), a1 = adot(q, alpha);
    const VecX<double> q2 = qdot(q + dt / 2 * q1, alpha + dt / 2 * a1), a2 = adot(q + dt / 2 * q1, alpha + dt / 2 * a1);
    const VecX<double> q3 = qdot(q + dt / 2 * q2, alpha + dt / 2 * a2), a3 = adot(q + dt / 2 * q2, alpha + dt / 2 * a2);
    const VecX<double> q4 = qdot(q + dt * q3, alpha + dt * a3), a4 = adot(q + dt * q3, alpha + dt * a3);
    VecX<double> qRef = q + dt / 6 * (q1 + 2 * q2 + 2 * q3 + q4);
    const VecX<double> aRef = alpha + dt / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    qRef.head<4>().normalize();
    ns::State<double> st{q, alpha};
    ns::step<double>(st, tau, dt, w);
    EXPECT_LT(relErr(VecX<double>(st.q), qRef), 1e-12) << "trial " << trial;
    EXPECT_LT(relErr(VecX<double>(st.alpha), aRef), 1e-12) << "trial " << trial;
  }
}

TEST(SceneMimic, DerivativesMatchLongDoubleDifferences)
{
  const MimicScene & s = scene();
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> u(-3, 3);
  const LD h = 1e-4L;
  double worstId = 0, worstFd = 0, worstMinv = 0;
  for(int trial = 0; trial < 3; ++trial)
  {
    VecX<double> q, alpha;
    s.randomState(rng, q, alpha, 2.0, 3.0); // no contact (see the top)
    const VecX<double> alphaD = VecX<double>::NullaryExpr(ns::nv, [&] { return u(rng); });
    const VecX<double> tau = VecX<double>::NullaryExpr(ns::nv, [&] { return u(rng); });
    const ns::Wrenches<double> w = randomWrenches(rng);
    const ns::Wrenches<LD> wl = cast<LD>(w);
    const VecX<LD> ql = q.cast<LD>(), al = alpha.cast<LD>(), adl = alphaD.cast<LD>(), tl = tau.cast<LD>();
    const auto id = ns::inverse_dynamics_derivatives<double>(q, alpha, alphaD, w);
    const auto fd = ns::forward_dynamics_derivatives<double>(q, alpha, tau, w);
    for(int k = 0; k < ns::nv; ++k)
    {
      const VecX<LD> e = VecX<LD>::Unit(ns::nv, k);
      const VecX<LD> idq = richardson([&](LD t) { return VecX<LD>(ns::inverse_dynamics<LD>(s.perturb(ql, k, t), al, adl, wl)); }, h);
      const VecX<LD> ida = richardson([&](LD t) { return VecX<LD>(ns::inverse_dynamics<LD>(ql, al + t * e, adl, wl)); }, h);
      const VecX<LD> fdq = richardson([&](LD t) { return VecX<LD>(ns::forward_dynamics<LD>(s.perturb(ql, k, t), al, tl, wl)); }, h);
      const VecX<LD> fda = richardson([&](LD t) { return VecX<LD>(ns::forward_dynamics<LD>(ql, al + t * e, tl, wl)); }, h);
      worstId = std::max({worstId, relErr(id.dtau_dq.col(k), idq.cast<double>()), relErr(id.dtau_dalpha.col(k), ida.cast<double>())});
      worstFd = std::max({worstFd, relErr(fd.dalphaD_dq.col(k), fdq.cast<double>()), relErr(fd.dalphaD_dalpha.col(k), fda.cast<double>())});
    }
    worstMinv = std::max(worstMinv, relErr(fd.Minv, MatX<double>(ns::mass_matrix<double>(q).inverse())));
    EXPECT_LT(relErr(fd.alphaD, ns::forward_dynamics<double>(q, alpha, tau, w)), 1e-14);
  }
  std::cout << "[ coupled scene ] worst relative error vs long double differences: d ID " << worstId << ", d FD " << worstFd
            << "; Minv vs H^-1 " << worstMinv << "\n";
  EXPECT_LT(worstId, 1e-9);
  EXPECT_LT(worstFd, 1e-9);
  EXPECT_LT(worstMinv, 1e-10);
}

TEST(SceneMimic, StepDerivativesMatchLongDoubleDifferences)
{
  const MimicScene & s = scene();
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-3, 3);
  const LD h = 1e-4L;
  const double dt = 1e-3;
  double worstA = 0, worstB = 0;
  for(int trial = 0; trial < 2; ++trial)
  {
    VecX<double> q, alpha;
    s.randomState(rng, q, alpha, 2.0, 3.0);
    const VecX<double> tau = VecX<double>::NullaryExpr(ns::nv, [&] { return u(rng); });
    const ns::Wrenches<double> w = randomWrenches(rng);
    const ns::Wrenches<LD> wl = cast<LD>(w);
    const VecX<LD> ql = q.cast<LD>(), al = alpha.cast<LD>(), tl = tau.cast<LD>();
    const auto d = ns::step_derivatives<double>(q, alpha, tau, dt, w);
    ns::State<LD> s0{ql, al};
    ns::step<LD>(s0, tl, LD(dt), wl);
    const VecX<LD> qRef = s.c.Gq.cast<LD>() * VecX<LD>(s0.q) + s.c.o.cast<LD>();
    // x+ in the tangent at the unperturbed q+: [q+_0 (-) q+ (coupled components); alpha+]
    auto next = [&](const VecX<LD> & q0, const VecX<LD> & a0, const VecX<LD> & t0) {
      ns::State<LD> st{q0, a0};
      ns::step<LD>(st, t0, LD(dt), wl);
      const VecX<LD> qf = s.c.Gq.cast<LD>() * VecX<LD>(st.q) + s.c.o.cast<LD>();
      VecX<LD> x(2 * ns::nv);
      x << s.selectTangent<LD>(rbd::configurationDifference(s.dynLD.mb(), qRef, qf)), VecX<LD>(st.alpha);
      return x;
    };
    for(int k = 0; k < ns::nv; ++k)
    {
      const VecX<LD> e = VecX<LD>::Unit(ns::nv, k);
      const VecX<LD> cq = richardson([&](LD t) { return next(s.perturb(ql, k, t), al, tl); }, h);
      const VecX<LD> ca = richardson([&](LD t) { return next(ql, al + t * e, tl); }, h);
      const VecX<LD> ct = richardson([&](LD t) { return next(ql, al, tl + t * e); }, h);
      worstA = std::max({worstA, relErr(d.A.col(k), cq.cast<double>()), relErr(d.A.col(ns::nv + k), ca.cast<double>())});
      worstB = std::max(worstB, relErr(d.B.col(k), ct.cast<double>()));
    }
  }
  std::cout << "[ coupled scene ] step_derivatives worst relative error vs long double differences: A " << worstA << ", B "
            << worstB << "\n";
  EXPECT_LT(worstA, 1e-9);
  EXPECT_LT(worstB, 1e-9);
}

} // namespace
