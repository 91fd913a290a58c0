#pragma once
// The programmatic scene headers (one per integrator) through plain function pointers (double),
// compiled in adapter.cpp with the generated-code checks (-Wall ... -Werror -fno-exceptions -fno-rtti).

namespace sgprog
{

struct StepAdapter
{
  const char * name;
  int nq, nv;
  void (*step)(double * q, double * alpha, const double * tau, double dt);
  /// next state (nq, nv), A (2 nv x 2 nv), B (2 nv x nv), column-major
  void (*stepDerivatives)(const double * q, const double * alpha, const double * tau, double dt, double * qNext,
                          double * alphaNext, double * A, double * B);
  /// step_derivatives<float> at a fixed state: all finite
  bool (*floatFinite)();
};

/// Integrator k of ProgrammaticScene.h.
const StepAdapter & adapter(int k);

} // namespace sgprog
