// Scene time stepping (see rbd/scene/Integrators.h), for double and long double.
#include "rbd/scene/Integrators.h"

#include <stdexcept>

#include <rbd/EulerIntegration.h>

namespace rbd::scene
{

template<class T>
SceneState<T> initialState(const SceneDynamicsTpl<T> & dyn)
{
  const MultiBodyTpl<T> & mb = dyn.mb();
  const Scene & scene = dyn.scene();
  SceneState<T> s;
  s.q.resize(mb.nrParams());
  s.alpha = Eigen::Matrix<T, Eigen::Dynamic, 1>::Zero(mb.nrDof());
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const JointTpl<T> & j = mb.joint(i);
    std::vector<T> q0 = j.zeroParam();
    if(auto it = scene.initialQ.find(j.name()); it != scene.initialQ.end())
    {
      if(static_cast<int>(it->second.size()) != j.params())
        throw std::invalid_argument("initialState: joint '" + j.name() + "': wrong number of q values");
      for(std::size_t c = 0; c < q0.size(); ++c) q0[c] = T(it->second[c]);
    }
    for(std::size_t c = 0; c < q0.size(); ++c) s.q[mb.jointPosInParam(i) + static_cast<Eigen::Index>(c)] = q0[c];
    if(auto it = scene.initialAlpha.find(j.name()); it != scene.initialAlpha.end())
    {
      if(static_cast<int>(it->second.size()) != j.dof())
        throw std::invalid_argument("initialState: joint '" + j.name() + "': wrong number of alpha values");
      for(int c = 0; c < j.dof(); ++c) s.alpha[mb.jointPosInDof(i) + c] = T(it->second[static_cast<std::size_t>(c)]);
    }
  }
  normalizeQuaternions(mb, s.q);
  return s;
}

template<class T>
void normalizeQuaternions(const MultiBodyTpl<T> & mb, Eigen::Matrix<T, Eigen::Dynamic, 1> & q)
{
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto type = mb.joint(i).type();
    if(type != JointType::Spherical && type != JointType::Free) continue;
    auto quat = q.template segment<4>(mb.jointPosInParam(i));
    quat /= quat.norm();
  }
}

template<class T>
void step(const SceneDynamicsTpl<T> & dyn, SceneState<T> & s, const typename SceneDynamicsTpl<T>::VectorX & tau,
          typename SceneDynamicsTpl<T>::Scalar dt, Integrator integrator,
          const typename SceneDynamicsTpl<T>::Wrenches & wrenches)
{
  using VectorX = Eigen::Matrix<T, Eigen::Dynamic, 1>;
  const MultiBodyTpl<T> & mb = dyn.mb();
  switch(integrator)
  {
    case Integrator::SemiImplicitEuler:
    {
      // alpha+ = alpha + dt a(q, alpha); q+ = q ⊕ alpha+ dt
      s.alpha += dt * dyn.forwardDynamics(s.q, s.alpha, tau, wrenches);
      s.q = integrateConfiguration(mb, s.q, VectorX(s.alpha * dt));
      break;
    }
    case Integrator::ExplicitEuler:
    {
      // q+ = q ⊕ alpha dt; alpha+ = alpha + dt a(q, alpha)
      const VectorX a = dyn.forwardDynamics(s.q, s.alpha, tau, wrenches);
      s.q = integrateConfiguration(mb, s.q, VectorX(s.alpha * dt));
      s.alpha += dt * a;
      break;
    }
    case Integrator::RK4:
    {
      // x+ = x + dt/6 (k1 + 2 k2 + 2 k3 + k4), k = (qdot, alphaD), q as a vector of R^nq
      auto deriv = [&](const VectorX & q, const VectorX & alpha, VectorX & qd, VectorX & ad) {
        qd = configurationDerivative(mb, q, alpha);
        ad = dyn.forwardDynamics(q, alpha, tau, wrenches);
      };
      VectorX q1, a1, q2, a2, q3, a3, q4, a4;
      deriv(s.q, s.alpha, q1, a1);
      deriv(VectorX(s.q + T(0.5) * dt * q1), VectorX(s.alpha + T(0.5) * dt * a1), q2, a2);
      deriv(VectorX(s.q + T(0.5) * dt * q2), VectorX(s.alpha + T(0.5) * dt * a2), q3, a3);
      deriv(VectorX(s.q + dt * q3), VectorX(s.alpha + dt * a3), q4, a4);
      s.q += dt / T(6) * (q1 + T(2) * q2 + T(2) * q3 + q4);
      s.alpha += dt / T(6) * (a1 + T(2) * a2 + T(2) * a3 + a4);
      normalizeQuaternions(mb, s.q);
      break;
    }
  }
}

template SceneState<double> initialState(const SceneDynamicsTpl<double> &);
template SceneState<long double> initialState(const SceneDynamicsTpl<long double> &);
template void step(const SceneDynamicsTpl<double> &, SceneState<double> &, const Eigen::VectorXd &, double, Integrator,
                   const std::vector<sva::ForceVec<double>> &);
template void step(const SceneDynamicsTpl<long double> &, SceneState<long double> &,
                   const Eigen::Matrix<long double, Eigen::Dynamic, 1> &, long double, Integrator,
                   const std::vector<sva::ForceVec<long double>> &);
template void normalizeQuaternions(const MultiBodyTpl<double> &, Eigen::VectorXd &);
template void normalizeQuaternions(const MultiBodyTpl<long double> &, Eigen::Matrix<long double, Eigen::Dynamic, 1> &);

} // namespace rbd::scene
