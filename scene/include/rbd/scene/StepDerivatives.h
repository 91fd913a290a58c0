#pragma once
// Derivatives of one integrator step of a scene (rbd/scene/Integrators.h, scene::step), for
// discrete-time MPC: x⁺ = F(x, tau) with x = (q, alpha) in the tangent space,
//   A = ∂x⁺/∂x (2 nv × 2 nv),  B = ∂x⁺/∂tau (2 nv × nv),
// rows and columns ordered [δq (nv); alpha (nv)]: δq is a tangent perturbation of q (q ⊕ δq,
// rbd::integrateConfiguration; for free and spherical joints [δω; δv] in the child frame, the
// coordinates of alpha), at the input q and, for the rows, at the output q⁺ (q⁺ ⊕ δq⁺). tau and
// the wrenches are held constant over the step (the wrenches are not differentiated). q must hold
// unit quaternions (every step leaves them so).
//
// With a = FD(q, alpha, tau), Fq = ∂a/∂q, Fa = ∂a/∂alpha, M⁻¹ = ∂a/∂tau
// (SceneDynamics::forwardDynamicsDerivatives) and Dq(w), Dw(w) the derivatives of q ⊕ w
// (rbd/IntegrationDerivatives.h):
//   SemiImplicitEuler: alpha⁺ = alpha + dt a, q⁺ = q ⊕ dt alpha⁺
//     ∂alpha⁺/∂(q, alpha, tau) = dt [Fq, Fa, M⁻¹] + [0, 1, 0]
//     ∂q⁺/∂(q, alpha, tau) = [Dq, 0, 0] + dt Dw ∂alpha⁺/∂(q, alpha, tau)          (w = dt alpha⁺)
//   ExplicitEuler: q⁺ = q ⊕ dt alpha, alpha⁺ = alpha + dt a
//     ∂q⁺/∂(q, alpha, tau) = [Dq, dt Dw, 0]                                       (w = dt alpha)
//     ∂alpha⁺ as above
//   RK4 (q as a vector of R^nq, rbd::configurationDerivative, quaternions normalised at the end):
//     the chain rule through the four stages. Each stage state (q_s, alpha_s) is carried with its
//     derivatives with respect to (δq, alpha, tau): ∂q_s (nq × 3 nv) starts as [P(q), 0, 0]
//     (P = configurationTangentMap), ∂alpha_s as [0, 1, 0]; a stage's slopes are
//       ∂k_q = Cq ∂q_s + Ca ∂alpha_s                       (configurationDerivativeJacobians)
//       ∂k_a = Fq(q_s) N(q_s) ∂q_s + Fa(q_s) ∂alpha_s + [0, 0, M⁻¹(q_s)]
//     (N = configurationTangentProjection: FD reads q_s's quaternions normalised); the stages
//     combine like the values, and δq⁺ = N(y) ∂y with y the step's q before normalisation.
// The step's result (q⁺, alpha⁺) comes with the derivatives: scene::step's, to rounding (its
// accelerations are those of forwardDynamicsDerivatives).

#include <vector>

#include <Eigen/Core>

#include "Integrators.h"
#include "SceneDynamics.h"

namespace rbd::scene
{

template<class T>
struct StepDerivativesTpl
{
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
  SceneState<T> next; ///< the stepped state (q⁺, alpha⁺)
  MatrixX A;          ///< ∂x⁺/∂x, 2 nv × 2 nv, x = [δq; alpha]
  MatrixX B;          ///< ∂x⁺/∂tau, 2 nv × nv
};
using StepDerivatives = StepDerivativesTpl<double>;

/// One step of size dt of the integrator from (q, alpha) under tau (and the wrenches), with its
/// derivatives (see the top of this file).
template<class T>
StepDerivativesTpl<T> stepDerivatives(const SceneDynamicsTpl<T> & dyn, const typename SceneDynamicsTpl<T>::VectorX & q,
                                      const typename SceneDynamicsTpl<T>::VectorX & alpha,
                                      const typename SceneDynamicsTpl<T>::VectorX & tau,
                                      typename SceneDynamicsTpl<T>::Scalar dt, Integrator integrator,
                                      const typename SceneDynamicsTpl<T>::Wrenches & wrenches = {});

extern template StepDerivativesTpl<double> stepDerivatives(const SceneDynamicsTpl<double> &, const Eigen::VectorXd &,
                                                           const Eigen::VectorXd &, const Eigen::VectorXd &, double,
                                                           Integrator, const std::vector<sva::ForceVec<double>> &);
extern template StepDerivativesTpl<long double> stepDerivatives(
    const SceneDynamicsTpl<long double> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
    const Eigen::Matrix<long double, Eigen::Dynamic, 1> &, const Eigen::Matrix<long double, Eigen::Dynamic, 1> &,
    long double, Integrator, const std::vector<sva::ForceVec<long double>> &);

} // namespace rbd::scene
