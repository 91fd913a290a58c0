#pragma once
// A generated robot seen through plain function pointers, so that one test program (compiled
// once) checks every robot, and each robot's generated header is compiled once, in its own
// adapter translation unit built with -Werror -fno-exceptions -fno-rtti.
//
// Layouts: a pose is 12 values (rotation row-major, then translation); matrices are column-major.

namespace rbdgentest
{

template<class S>
struct GeneratedFunctions
{
  void (*forwardKinematics)(const S * q, S * poses);       ///< nbodies x 12
  void (*kinematicsPoses)(const S * q, S * poses);         ///< via kinematics(): nbodies x 12
  void (*inverseDynamics)(const S * q, const S * alpha, const S * alphaD, S * tau);
  void (*inverseDynamicsExt)(const S * q, const S * alpha, const S * alphaD, const S * fext, S * tau); ///< fext: nbodies x 6
  void (*nonlinearEffects)(const S * q, const S * alpha, S * tau);
  void (*velocityTorques)(const S * q, const S * alpha, S * tau);
  void (*gravityTorques)(const S * q, S * tau);
  void (*massMatrix)(const S * q, S * H);                  ///< nv x nv
  /// mass_matrix_packed(q) put back into nv x nv by mass_matrix_entries (both triangles; the
  /// entries it leaves out are 0)
  void (*massMatrixPacked)(const S * q, S * H);
  void (*forwardDynamics)(const S * q, const S * alpha, const S * tau, S * alphaD);
  void (*forwardDynamicsAba)(const S * q, const S * alpha, const S * tau, S * alphaD);
  void (*forwardDynamicsCrba)(const S * q, const S * alpha, const S * tau, S * alphaD);
  void (*jacobian)(int body, const S * q, S * J);          ///< via kinematics(): 6 x nv
  void (*jacobianQ)(int body, const S * q, S * J);         ///< jacobian(body, q): support path only
  void (*jacobianPoint)(int body, const S * q, const S * point, S * J);    ///< jacobian(body, q, point)
  void (*jacobianKinPoint)(int body, const S * q, const S * point, S * J); ///< jacobian(body, kinematics(q), point)
  void (*centerOfMass)(const S * q, S * com);              ///< 3, center_of_mass(q)
  void (*centerOfMassKin)(const S * q, S * com);           ///< 3, center_of_mass(kinematics(q))
  void (*bodyVelocities)(const S * q, const S * alpha, S * v);                       ///< nbodies x 6
  void (*bodyAccelerations)(const S * q, const S * alpha, const S * alphaD, S * a);  ///< nbodies x 6
  void (*jacobianDotTimesAlpha)(int body, const S * q, const S * alpha, S * out);   ///< 6, from q: support path only
  void (*jacobianDotTimesAlphaKin)(int body, const S * q, const S * alpha, S * out); ///< 6, via kinematics()
  void (*comJacobian)(const S * q, S * J);                 ///< 3 x nv
  void (*centroidalMomentumMatrix)(const S * q, S * A);    ///< 6 x nv
  /// nv x nv each; null when generated without derivatives
  void (*inverseDynamicsDerivatives)(const S * q, const S * alpha, const S * alphaD, S * dtauDq, S * dtauDalpha);
  /// alphaD (nv), then nv x nv each; null without derivatives or forward dynamics
  void (*forwardDynamicsDerivatives)(const S * q, const S * alpha, const S * tau, S * alphaD, S * dalphaDDq,
                                     S * dalphaDDalpha, S * Minv);
};

struct GeneratedRobot
{
  const char * name;
  const char * urdf;         ///< URDF path, or empty for a programmatic model
  bool floatingBase;
  const char * baseLink;     ///< empty: the URDF root
  int programmaticModel;     ///< index into programmaticModel(), -1 for a URDF
  int nq, nv, nbodies;
  const char * const * bodyNames;
  const char * const * dofNames;
  const char * forwardDynamicsAlgorithm;
  bool hasForwardDynamics;   ///< false: singular mass matrix, the forwardDynamics* pointers are null
  GeneratedFunctions<double> d;   ///< the full model (NAME::independent: mimic joints as dofs)
  GeneratedFunctions<float> f;
  /// The robot's own API (namespace NAME): mimic joints coupled, the same as d without mimic joints.
  int coupledNq, coupledNv;
  const char * const * coupledDofNames;
  bool coupledHasForwardDynamics;
  GeneratedFunctions<double> coupled;
};

} // namespace rbdgentest
