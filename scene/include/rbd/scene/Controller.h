#pragma once
// The simple controller of `rbdgen simulate` (Scene::controller):
//   ZeroTorque: tau = 0
//   PdHold:     tau_i = kp (q_target,i - q_i) - kd alpha_i on every 1-dof joint (other dofs: 0);
//               q_target from <target>, else the joint's initial position.
//   PdGravity:  the PD hold plus g(q), the scene's gravity torques (SceneDynamics::gravityTorques).

#include <vector>

#include <Eigen/Core>

#include "Integrators.h"

namespace rbd::scene
{

template<class T>
class SceneControllerTpl
{
public:
  using VectorX = Eigen::Matrix<T, Eigen::Dynamic, 1>;

  /// Targets resolved once: <target> positions, else the joint's q in `initial`. dyn must outlive
  /// the controller (PdGravity evaluates g(q) with it).
  SceneControllerTpl(const SceneDynamicsTpl<T> & dyn, const SceneState<T> & initial);

  /// Joint torques (size nv) at the state (q, alpha).
  VectorX torque(const VectorX & q, const VectorX & alpha) const;

private:
  struct Pd
  {
    int paramIndex, dofIndex;
    T target;
  };
  const SceneDynamicsTpl<T> * dyn_ = nullptr; ///< for g(q) (PdGravity)
  int nv_ = 0;
  bool pd_ = false, gravity_ = false;
  T kp_ = T(0), kd_ = T(0);
  std::vector<Pd> joints_;
};

using SceneController = SceneControllerTpl<double>;

extern template class SceneControllerTpl<double>;
extern template class SceneControllerTpl<long double>;

} // namespace rbd::scene
