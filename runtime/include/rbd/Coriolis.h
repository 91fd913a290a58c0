#pragma once
// The Coriolis matrix C(q, alpha): C alpha is the velocity-product term of the equations of motion
// (Coriolis and centrifugal, no gravity: inverse dynamics at alphaD = 0 with zero gravity and no
// external force), and Mdot - 2C is skew-symmetric. C itself is not unique; this is RBDyn's
// factorisation (Bjerkeng & Pettersen, "A new Coriolis matrix factorization", ICRA 2012):
//   C = sum_i m_i J_v,i^T Jdot_v,i + J_w,i^T (I_i Jdot_w,i + w_i^ I_i J_w,i)
// with J_i = [J_w,i; J_v,i] the Jacobian of body i at its centre of mass in world axes (Jacobian.h),
// I_i = E_0_i^T I_c,i E_0_i its rotational inertia about the centre of mass in world axes and w_i its
// angular velocity in world axes. (M = sum_i m_i J_v^T J_v + J_w^T I J_w, and
// d/dt I_i = w_i^ I_i - I_i w_i^, hence the skew symmetry.)

#include <vector>

#include <rbd/Jacobian.h>

namespace rbd
{

template<typename T>
class CoriolisTpl
{
public:
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

  CoriolisTpl() = default;
  explicit CoriolisTpl(const MultiBodyTpl<T> & mb);

  /// Use bodyPosW, motionSubspace (forwardKinematics), bodyVelB and jointVelocity
  /// (forwardVelocity). Return C (nrDof x nrDof).
  const MatrixX & coriolis(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc);

private:
  std::vector<JacobianTpl<T>> jacs_;  ///< body i at its centre of mass
  std::vector<Blocks> paths_;         ///< jacs_[i].compactPath(mb)
  std::vector<sva::Matrix3<T>> Ic_;   ///< rotational inertia about the centre of mass, body axes
  MatrixX C_;
};

using Coriolis = CoriolisTpl<double>;

template<typename T>
CoriolisTpl<T>::CoriolisTpl(const MultiBodyTpl<T> & mb) : C_(MatrixX::Zero(mb.nrDof(), mb.nrDof()))
{
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto & I = mb.body(i).inertia();
    const sva::Vector3<T> c = I.mass() > T(0) ? sva::Vector3<T>(I.momentum() / I.mass()) : sva::Vector3<T>::Zero();
    jacs_.emplace_back(mb, mb.body(i).name(), c);
    paths_.push_back(jacs_.back().compactPath(mb));
    // parallel axis theorem: I_c = I_O - m c^T^ c^ = I_O + m c^ c^
    const sva::Matrix3<T> cx = sva::vector3ToCrossMatrix(c);
    Ic_.push_back(I.inertia() + I.mass() * cx * cx);
  }
}

template<typename T>
const typename CoriolisTpl<T>::MatrixX & CoriolisTpl<T>::coriolis(const MultiBodyTpl<T> & mb,
                                                                  const MultiBodyConfigTpl<T> & mbc)
{
  C_.setZero();
  for(int i = 0; i < mb.nrBodies(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    if(jacs_[k].dof() == 0) continue; // (no block of an empty matrix: Eigen offsets a null pointer)
    const MatrixX J = jacs_[k].jacobian(mb, mbc);
    const MatrixX Jd = jacs_[k].jacobianDot(mb, mbc);
    const sva::Matrix3<T> Et = mbc.bodyPosW[k].rotation().transpose(); // body -> world axes
    const sva::Matrix3<T> Iw = Et * Ic_[k] * Et.transpose();
    const sva::Vector3<T> w = Et * mbc.bodyVelB[k].angular();
    const auto Jw = J.template topRows<3>(), Jv = J.template bottomRows<3>();
    // m J_v^T Jdot_v + J_w^T (I Jdot_w + w^ I J_w)
    const MatrixX Ci = mb.body(i).inertia().mass() * Jv.transpose() * Jd.template bottomRows<3>() +
                       Jw.transpose() * (Iw * Jd.template topRows<3>() + sva::vector3ToCrossMatrix(w) * Iw * Jw);
    jacs_[k].expandAdd(paths_[k], Ci, C_);
  }
  return C_;
}

extern template class CoriolisTpl<double>;
extern template class CoriolisTpl<long double>;

} // namespace rbd
