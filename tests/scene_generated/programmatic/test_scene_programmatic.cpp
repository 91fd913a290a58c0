// Step derivatives on a scene built in code with every joint type of the runtime (URDF has no
// spherical or cylindrical joint; ProgrammaticScene.h), for each integrator:
//  - the runtime's rbd::scene::stepDerivatives against long double central differences with one
//    Richardson step of rbd::scene::step (q columns along q ⊕ t e_k, outputs compared in the
//    tangent at q⁺ with rbd::configurationDifference). dt = 50 ms, h = 1e-4 along q, alpha and tau:
//    truncation O(h⁴ f⁽⁵⁾) ~1e-13 (friction v_s = 0.1), round-off eps |x⁺|/h ~1e-12 with the large
//    accelerations of this random tree (cond(H) up to 9e4; at h = 3e-5 the errors grow: round-off
//    dominates); bound 1e-11 relative to max(1, |A|), as tests/scene/test_step_derivatives;
//  - the generated step and step_derivatives (emitted by make_programmatic_scenes through
//    emitDynamicsHeader, compiled with the generated-code checks) against the runtime in double at
//    dt = 1 ms and 50 ms (rotations up to ~0.2 rad per step): the stepped state within the forward
//    dynamics bound of the generated-code tests, 1e-12 max(1, cond(H)/1e3) (two solvers, the
//    accelerations enter times dt); A and B 1e-10 max(1, cond(H)/1e3), the bound of
//    tests/scene_generated scaled the same way (their velocity rows are dt times forward dynamics
//    derivatives that two solvers give ~cond(H) eps apart). cond(H) of this random tree is printed.
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <rbd/IntegrationDerivatives.h>
#include <rbd/scene/StepDerivatives.h>

#include "ProgrammaticAdapter.h"
#include "ProgrammaticScene.h"
#include "TestModels.h"

namespace
{

namespace sc = rbd::scene;
using LD = long double;
template<class T>
using VecX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
template<class T>
using MatX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

template<class T>
sc::SceneState<T> randomState(const rbd::MultiBodyTpl<T> & mb, std::mt19937 & rng)
{
  std::uniform_real_distribution<double> u(-1, 1);
  sc::SceneState<T> s{VecX<T>(mb.nrParams()), VecX<T>(mb.nrDof())};
  for(Eigen::Index i = 0; i < s.q.size(); ++i) s.q[i] = T(u(rng));
  for(Eigen::Index i = 0; i < s.alpha.size(); ++i) s.alpha[i] = T(2 * u(rng));
  sc::normalizeQuaternions(mb, s.q);
  return s;
}

template<class F>
VecX<LD> richardson(F f, LD h)
{
  const VecX<LD> d1 = (f(h) - f(-h)) / (2 * h), d2 = (f(h / 2) - f(-h / 2)) / h;
  return VecX<LD>((4 * d2 - d1) / 3);
}

class Programmatic : public ::testing::TestWithParam<int>
{
};

TEST_P(Programmatic, RuntimeMatchesLongDoubleDifferences)
{
  const sc::SceneRobot sr = sgprog::sceneRobot();
  const sc::Scene scene = sgprog::scene(sgprog::integrator(GetParam()));
  const sc::SceneDynamicsTpl<LD> dyn(sr, scene);
  const int nv = dyn.nv();
  std::mt19937 rng(40 + static_cast<unsigned>(GetParam()));
  double worstA = 0, worstB = 0;
  for(int trial = 0; trial < 3; ++trial)
  {
    const auto s = randomState(dyn.mb(), rng);
    const VecX<LD> tau = VecX<LD>::Random(nv) * 2;
    const LD dt = 0.05L;
    const auto d = sc::stepDerivatives(dyn, s.q, s.alpha, tau, dt, scene.integrator);
    auto at = [&](const VecX<LD> & q, const VecX<LD> & a, const VecX<LD> & t) {
      sc::SceneState<LD> x{q, a};
      sc::step(dyn, x, t, dt, scene.integrator);
      VecX<LD> out(2 * nv);
      out << rbd::configurationDifference(dyn.mb(), d.next.q, x.q), x.alpha;
      return out;
    };
    MatX<LD> nA(2 * nv, 2 * nv), nB(2 * nv, nv);
    for(int k = 0; k < nv; ++k)
    {
      const VecX<LD> e = VecX<LD>::Unit(nv, k);
      nA.col(k) = richardson([&](LD t) { return at(rbd::integrateConfiguration(dyn.mb(), s.q, VecX<LD>(e * t)), s.alpha, tau); },
                             1e-4L);
      nA.col(nv + k) = richardson([&](LD t) { return at(s.q, VecX<LD>(s.alpha + e * t), tau); }, 1e-4L);
      nB.col(k) = richardson([&](LD t) { return at(s.q, s.alpha, VecX<LD>(tau + e * t)); }, 1e-4L);
    }
    worstA = std::max(worstA, rbdtest::relErr(d.A, nA));
    worstB = std::max(worstB, rbdtest::relErr(d.B, nB));
  }
  EXPECT_LT(worstA, 1e-11);
  EXPECT_LT(worstB, 1e-11);
  std::cout << "[ measured ] " << sgprog::headerName(GetParam()) << " (every joint type, dt 50 ms): runtime A " << worstA
            << ", B " << worstB << " vs long double differences\n";
}

TEST_P(Programmatic, GeneratedMatchesRuntime)
{
  const sgprog::StepAdapter & g = sgprog::adapter(GetParam());
  const sc::SceneRobot sr = sgprog::sceneRobot();
  const sc::Scene scene = sgprog::scene(sgprog::integrator(GetParam()));
  const sc::SceneDynamics dyn(sr, scene);
  ASSERT_EQ(g.nq, dyn.nq());
  ASSERT_EQ(g.nv, dyn.nv());
  const int nq = g.nq, nv = g.nv;
  std::mt19937 rng(50 + static_cast<unsigned>(GetParam()));
  double worstX = 0, worstStep = 0, worstA = 0, worstB = 0, cond = 1;
  for(double dt : {1e-3, 0.05})
    for(int trial = 0; trial < 20; ++trial)
    {
      const auto s = randomState(dyn.mb(), rng);
      const Eigen::VectorXd tau = Eigen::VectorXd::Random(nv) * 2;
      const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dyn.massMatrix(s.q)).eigenvalues();
      cond = std::max(cond, ev.maxCoeff() / ev.minCoeff());
      const sc::StepDerivatives r = sc::stepDerivatives(dyn, s.q, s.alpha, tau, dt, scene.integrator);
      Eigen::VectorXd qn(nq), an(nv);
      Eigen::MatrixXd A(2 * nv, 2 * nv), B(2 * nv, nv);
      g.stepDerivatives(s.q.data(), s.alpha.data(), tau.data(), dt, qn.data(), an.data(), A.data(), B.data());
      Eigen::VectorXd x(nq + nv), xr(nq + nv);
      x << qn, an;
      xr << r.next.q, r.next.alpha;
      worstX = std::max(worstX, rbdtest::relErr(x, xr));
      worstA = std::max(worstA, rbdtest::relErr(A, r.A));
      worstB = std::max(worstB, rbdtest::relErr(B, r.B));
      // step() itself
      sc::SceneState<double> rs = s;
      sc::step(dyn, rs, tau, dt, scene.integrator);
      Eigen::VectorXd q = s.q, a = s.alpha;
      g.step(q.data(), a.data(), tau.data(), dt);
      x << q, a;
      xr << rs.q, rs.alpha;
      worstStep = std::max(worstStep, rbdtest::relErr(x, xr));
    }
  const double scale = std::max(1.0, cond / 1e3);
  EXPECT_LT(worstX, 1e-12 * scale);
  EXPECT_LT(worstStep, 1e-12 * scale);
  EXPECT_LT(worstA, 1e-10 * scale);
  EXPECT_LT(worstB, 1e-10 * scale);
  EXPECT_TRUE(g.floatFinite());
  std::cout << "[ measured ] " << g.name << " (max cond(H) " << cond << ") generated vs runtime: step " << worstStep << ", step_derivatives x+ " << worstX
            << ", A " << worstA << ", B " << worstB << "\n";
}

INSTANTIATE_TEST_SUITE_P(Integrators, Programmatic, ::testing::Range(0, sgprog::kIntegrators),
                         [](const ::testing::TestParamInfo<int> & i) { return sgprog::headerName(i.param); });

} // namespace
