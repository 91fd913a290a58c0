#pragma once
// A scene-specialised generated header seen through plain function pointers (double), so one test
// program checks every scene; each header is compiled once, in its own adapter translation unit
// (-Wall -Wextra -Wpedantic -Wshadow -Werror -fno-exceptions -fno-rtti, double and float).
// A function the scene does not call for is a null pointer. Matrices are column-major; a pose is
// 12 values (rotation row-major, then translation); wrenches: 6 per scene wrench, [n; f].

namespace scenegentest
{

struct SceneAdapter
{
  const char * name;
  const char * sceneFile;
  const char * headerPath;
  int nq, nv, nwrenches, ncontacts;
  bool hasForwardDynamics;
  void (*massMatrix)(const double * q, double * H);
  /// mass_matrix_packed(q) put back into nv x nv by mass_matrix_entries (0 for the entries left out)
  void (*massMatrixPacked)(const double * q, double * H);
  void (*inverseDynamics)(const double * q, const double * alpha, const double * alphaD, const double * w, double * tau);
  void (*forwardDynamics)(const double * q, const double * alpha, const double * tau, const double * w, double * alphaD);
  void (*generalizedBias)(const double * q, const double * alpha, const double * w, double * out);
  void (*gravityTorques)(const double * q, double * out);
  void (*velocityTorques)(const double * q, const double * alpha, double * out);
  void (*nonlinearEffects)(const double * q, const double * alpha, double * out);
  void (*contactForces)(const double * q, const double * alpha, double * out); ///< 3 per contact
  void (*step)(double * q, double * alpha, const double * tau, double dt, const double * w);
  void (*integrate)(const double * q, const double * dq, double * out);
  void (*initialState)(double * q, double * alpha);
  int nposes;
  const char * const * poseLinks;
  void (*pose)(int i, const double * q, double * out);
  int njacobians;
  const char * const * jacobianLinks;
  void (*jacobian)(int i, const double * q, double * J);
  void (*centerOfMass)(const double * q, double * out);
  void (*centroidalMomentum)(const double * q, const double * alpha, double * out);
  void (*kineticEnergy)(const double * q, const double * alpha, double * out);
  void (*potentialEnergy)(const double * q, double * out);
  void (*energy)(const double * q, const double * alpha, double * out);
  /// Derivatives (null without <derivatives/>): nv x nv each; fd: alphaD (nv) then three nv x nv.
  void (*inverseDynamicsDerivatives)(const double * q, const double * alpha, const double * alphaD, const double * w,
                                     double * dq, double * da);
  void (*forwardDynamicsDerivatives)(const double * q, const double * alpha, const double * tau, const double * w,
                                     double * alphaD, double * dq, double * da, double * Minv);
  /// Every float function once at the initial state with random-ish inputs: all results finite.
  bool (*floatFinite)();
  /// step_derivatives (null without <derivatives/> or forward dynamics): the stepped state (nq, nv),
  /// A (2 nv x 2 nv) and B (2 nv x nv).
  void (*stepDerivatives)(const double * q, const double * alpha, const double * tau, double dt, const double * w,
                          double * qNext, double * alphaNext, double * A, double * B);
};

} // namespace scenegentest
