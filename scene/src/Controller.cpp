// The simulate controller (see rbd/scene/Controller.h), for double and long double.
#include "rbd/scene/Controller.h"

namespace rbd::scene
{

template<class T>
SceneControllerTpl<T>::SceneControllerTpl(const SceneDynamicsTpl<T> & dyn, const SceneState<T> & initial)
: dyn_(&dyn), nv_(dyn.nv())
{
  const Controller & c = dyn.scene().controller;
  gravity_ = c.type == Controller::Type::PdGravity;
  pd_ = c.type == Controller::Type::PdHold || gravity_;
  kp_ = T(c.kp);
  kd_ = T(c.kd);
  if(!pd_) return;
  const MultiBodyTpl<T> & mb = dyn.mb();
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    if(mb.joint(i).dof() != 1 || mb.joint(i).params() != 1) continue;
    const int pq = mb.jointPosInParam(i);
    auto it = c.target.find(mb.joint(i).name());
    joints_.push_back(Pd{pq, mb.jointPosInDof(i), it != c.target.end() ? T(it->second) : initial.q[pq]});
  }
}

template<class T>
typename SceneControllerTpl<T>::VectorX SceneControllerTpl<T>::torque(const VectorX & q, const VectorX & alpha) const
{
  // tau = g(q) (PdGravity only) + PD
  VectorX tau = gravity_ ? dyn_->gravityTorques(q) : VectorX::Zero(nv_);
  // tau_i = kp (q_target - q_i) - kd alpha_i
  for(const Pd & j : joints_) tau[j.dofIndex] += kp_ * (j.target - q[j.paramIndex]) - kd_ * alpha[j.dofIndex];
  return tau;
}

template class SceneControllerTpl<double>;
template class SceneControllerTpl<long double>;

} // namespace rbd::scene
