// The programmatic scene headers (make_programmatic_scenes) compiled for double and float.
#include <sgprog_explicit/dynamics.hpp>
#include <sgprog_rk4/dynamics.hpp>
#include <sgprog_semi/dynamics.hpp>

#include "ProgrammaticAdapter.h"

namespace
{
template<class M>
void store(const M & m, double * out)
{
  Eigen::Map<M> map(out);
  map = m;
}
} // namespace

#define SGPROG_ADAPTER(NS)                                                                                               \
  namespace NS##_adapter                                                                                                 \
  {                                                                                                                      \
  void step(double * q, double * a, const double * tau, double dt)                                                       \
  {                                                                                                                      \
    NS::State<double> s{Eigen::Map<const NS::Config<double>>(q), Eigen::Map<const NS::Tangent<double>>(a)};            \
    NS::step<double>(s, Eigen::Map<const NS::Tangent<double>>(tau), dt);                                                  \
    store(s.q, q);                                                                                                        \
    store(s.alpha, a);                                                                                                   \
  }                                                                                                                      \
  void stepDerivatives(const double * q, const double * a, const double * tau, double dt, double * qn, double * an,      \
                       double * A, double * B)                                                                           \
  {                                                                                                                      \
    const auto d = NS::step_derivatives<double>(Eigen::Map<const NS::Config<double>>(q),                                 \
                                                Eigen::Map<const NS::Tangent<double>>(a),                                \
                                                Eigen::Map<const NS::Tangent<double>>(tau), dt);                         \
    store(d.next.q, qn);                                                                                                  \
    store(d.next.alpha, an);                                                                                             \
    store(d.A, A);                                                                                                        \
    store(d.B, B);                                                                                                        \
  }                                                                                                                      \
  bool floatFinite()                                                                                                     \
  {                                                                                                                      \
    NS::State<float> s = NS::initial_state<float>();                                                                     \
    for(int i = 0; i < NS::nv; ++i) s.alpha[i] = 0.1f * static_cast<float>(i % 3 - 1);                                   \
    const auto d = NS::step_derivatives<float>(s.q, s.alpha, NS::Tangent<float>::Constant(0.5f), 1e-3f);                 \
    return d.next.q.allFinite() && d.next.alpha.allFinite() && d.A.allFinite() && d.B.allFinite();                      \
  }                                                                                                                      \
  const sgprog::StepAdapter a{#NS, NS::nq, NS::nv, &step, &stepDerivatives, &floatFinite};                              \
  }

SGPROG_ADAPTER(sgprog_semi)
SGPROG_ADAPTER(sgprog_explicit)
SGPROG_ADAPTER(sgprog_rk4)

namespace sgprog
{
const StepAdapter & adapter(int k)
{
  return k == 0 ? sgprog_semi_adapter::a : (k == 1 ? sgprog_explicit_adapter::a : sgprog_rk4_adapter::a);
}
} // namespace sgprog
