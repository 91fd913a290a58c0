// Cost of each scene effect on one robot (the quadruped, floating base): the same generated
// functions from scenes that differ by one effect, and hand-trimmed baselines from the plain
// header showing that a disabled effect costs nothing:
//   - gravity only:      plain gravity_torques            vs scene nonlinear_effects / generalized_bias
//   - gravity + velocity: plain forward_dynamics_crba     vs scene forward_dynamics (same physics)
//   - each effect added:  forward_dynamics of bare, gravity, gravity_velocity, joint_effects, contacts
// Scenes: tests/scene_generated/scenes/{quadruped_bare,bench_*}.xml (checked against the runtime by
// tests/scene_generated). Inputs are fixed seeded random states, cycled through.
#include <array>
#include <random>

#include <benchmark/benchmark.h>

#include <bq_bare/dynamics.hpp>
#include <bq_contacts/dynamics.hpp>
#include <bq_gravity/dynamics.hpp>
#include <bq_gravity_velocity/dynamics.hpp>
#include <bq_joint_effects/dynamics.hpp>
#include <bq_plain/dynamics.hpp>

namespace
{
constexpr int kStates = 64;
static_assert(bq_plain::nq == bq_bare::nq && bq_plain::nv == bq_bare::nv, "same robot");
using Config = bq_plain::Config<double>;
using Tangent = bq_plain::Tangent<double>;

struct States
{
  std::array<Config, kStates> q;
  std::array<Tangent, kStates> alpha, tau;
  States()
  {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-1, 1);
    for(int s = 0; s < kStates; ++s)
    {
      for(int i = 0; i < bq_plain::nq; ++i) q[s][i] = u(rng);
      q[s].head<4>().normalize();
      q[s][6] = 0.3 + 0.05 * u(rng); // trunk height: some feet in the ground
      for(int i = 0; i < bq_plain::nv; ++i) alpha[s][i] = u(rng), tau[s][i] = u(rng);
    }
  }
};
const States & states()
{
  static const States s;
  return s;
}

template<class F>
void run(benchmark::State & st, F && f)
{
  const States & s = states();
  int k = 0;
  for(auto _ : st)
  {
    benchmark::DoNotOptimize(f(s, k));
    k = (k + 1) % kStates;
  }
}

// --- gravity only: the plain header's gravity_torques is the hand-trimmed version ------------------
void Plain_GravityTorques(benchmark::State & st)
{
  run(st, [](const States & s, int k) { return bq_plain::gravity_torques<double>(s.q[k]); });
}
void SceneGravity_NonlinearEffects(benchmark::State & st)
{
  run(st, [](const States & s, int k) { return bq_gravity::nonlinear_effects<double>(s.q[k], s.alpha[k]); });
}
void SceneGravity_GeneralizedBias(benchmark::State & st)
{
  run(st, [](const States & s, int k) { return bq_gravity::generalized_bias<double>(s.q[k], s.alpha[k]); });
}

// --- gravity + velocity terms: the plain header's CRBA forward dynamics is the same physics -------
void Plain_ForwardDynamicsCrba(benchmark::State & st)
{
  run(st, [](const States & s, int k) { return bq_plain::forward_dynamics_crba<double>(s.q[k], s.alpha[k], s.tau[k]); });
}
void Plain_NonlinearEffects(benchmark::State & st)
{
  run(st, [](const States & s, int k) { return bq_plain::nonlinear_effects<double>(s.q[k], s.alpha[k]); });
}
void SceneGravityVelocity_GeneralizedBias(benchmark::State & st)
{
  run(st, [](const States & s, int k) { return bq_gravity_velocity::generalized_bias<double>(s.q[k], s.alpha[k]); });
}

// --- forward dynamics, one effect added at a time ---------------------------------------------------
#define RBDGEN_SCENE_FD(ns)                                                                                      \
  void ns##_ForwardDynamics(benchmark::State & st)                                                               \
  {                                                                                                              \
    run(st, [](const States & s, int k) { return ns::forward_dynamics<double>(s.q[k], s.alpha[k], s.tau[k]); }); \
  }
RBDGEN_SCENE_FD(bq_bare)
RBDGEN_SCENE_FD(bq_gravity)
RBDGEN_SCENE_FD(bq_gravity_velocity)
RBDGEN_SCENE_FD(bq_joint_effects)
RBDGEN_SCENE_FD(bq_contacts)
#undef RBDGEN_SCENE_FD

void SceneContacts_ContactForces(benchmark::State & st)
{
  run(st, [](const States & s, int k) { return bq_contacts::contact_forces<double>(s.q[k], s.alpha[k]); });
}
void SceneGravityVelocity_Step(benchmark::State & st)
{
  const States & s = states();
  bq_gravity_velocity::State<double> x{s.q[0], s.alpha[0]};
  for(auto _ : st)
  {
    bq_gravity_velocity::step<double>(x, s.tau[0], 1e-4);
    benchmark::DoNotOptimize(x.q);
  }
}

} // namespace

BENCHMARK(Plain_GravityTorques);
BENCHMARK(SceneGravity_NonlinearEffects);
BENCHMARK(SceneGravity_GeneralizedBias);
BENCHMARK(Plain_NonlinearEffects);
BENCHMARK(SceneGravityVelocity_GeneralizedBias);
BENCHMARK(Plain_ForwardDynamicsCrba);
BENCHMARK(bq_gravity_velocity_ForwardDynamics);
BENCHMARK(bq_bare_ForwardDynamics);
BENCHMARK(bq_gravity_ForwardDynamics);
BENCHMARK(bq_joint_effects_ForwardDynamics);
BENCHMARK(bq_contacts_ForwardDynamics);
BENCHMARK(SceneContacts_ContactForces);
BENCHMARK(SceneGravityVelocity_Step);
BENCHMARK_MAIN();
