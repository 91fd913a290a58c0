#pragma once
// Time stepping of a scene (semantics of each Integrator in Scene.h) and its initial state.
//   SemiImplicitEuler: a = FD(q, alpha); alpha+ = alpha + dt a; q+ = q ⊕ (alpha+ dt)
//   ExplicitEuler:     a = FD(q, alpha); q+ = q ⊕ (alpha dt); alpha+ = alpha + dt a
//   RK4: classical RK4 on x = (q, alpha) with xdot = (configurationDerivative(q, alpha), FD(q, alpha)),
//        q treated as a vector of R^nq (stage configurations are not normalised: a non-unit
//        quaternion stands for its normalisation in the runtime); quaternions normalised after the step.
// ⊕ is rbd::integrateConfiguration (exact exponential per joint). tau and the wrenches are held
// constant over the step.

#include <vector>

#include <Eigen/Core>

#include "SceneDynamics.h"

namespace rbd::scene
{

template<class T>
struct SceneState
{
  Eigen::Matrix<T, Eigen::Dynamic, 1> q;     ///< size nq
  Eigen::Matrix<T, Eigen::Dynamic, 1> alpha; ///< size nv
};

/// q from <initial> (default: zero, identity quaternions), alpha from <initial> (default: zero).
template<class T>
SceneState<T> initialState(const SceneDynamicsTpl<T> & dyn);

/// One step of size dt of the given integrator, in place (T is deduced from dyn only).
template<class T>
void step(const SceneDynamicsTpl<T> & dyn, SceneState<T> & state, const typename SceneDynamicsTpl<T>::VectorX & tau,
          typename SceneDynamicsTpl<T>::Scalar dt, Integrator integrator,
          const typename SceneDynamicsTpl<T>::Wrenches & wrenches = {});

/// Normalise the quaternions of the Spherical and Free joints of q, in place.
template<class T>
void normalizeQuaternions(const MultiBodyTpl<T> & mb, Eigen::Matrix<T, Eigen::Dynamic, 1> & q);

extern template SceneState<double> initialState(const SceneDynamicsTpl<double> &);
extern template SceneState<long double> initialState(const SceneDynamicsTpl<long double> &);
extern template void step(const SceneDynamicsTpl<double> &, SceneState<double> &, const Eigen::VectorXd &, double,
                          Integrator, const std::vector<sva::ForceVec<double>> &);
extern template void step(const SceneDynamicsTpl<long double> &, SceneState<long double> &,
                          const Eigen::Matrix<long double, Eigen::Dynamic, 1> &, long double, Integrator,
                          const std::vector<sva::ForceVec<long double>> &);
extern template void normalizeQuaternions(const MultiBodyTpl<double> &, Eigen::VectorXd &);
extern template void normalizeQuaternions(const MultiBodyTpl<long double> &, Eigen::Matrix<long double, Eigen::Dynamic, 1> &);

} // namespace rbd::scene
