#pragma once
// Inverse statics (RBDyn's InverseStatics, header IS.h): the joint torques that hold the system at
// rest under gravity and the external forces, i.e. inverse dynamics at alpha = alphaD = 0:
//   a_i = X_0_i a_0   (a_0 = [0; gravity], body coordinates)
//   f_i = I_i a_i - X_0_i^* f_ext_i,   f_λ(i) += X_p_i^T f_i,   tau_i = S_i^T f_i
// and its derivative with respect to q (tangent convention of IDDerivatives.h: d/dq_m along
// q ⊕ ε e_m), the external forces held constant in world coordinates at the world origin, plus
// optionally the user's derivatives of those forces.

#include <vector>

#include <rbd/Checks.h>
#include <rbd/IDDerivatives.h>

namespace rbd
{

template<typename T>
class InverseStaticsTpl
{
public:
  using MatrixX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

  InverseStaticsTpl() = default;
  explicit InverseStaticsTpl(const MultiBodyTpl<T> & mb)
  : f_(static_cast<std::size_t>(mb.nrBodies()), sva::ForceVec<T>::Zero()), idd_(mb)
  {
    for(const auto & j : mb.joints()) jointTorqueDiff_.push_back(MatrixX::Zero(j.dof(), mb.nrDof()));
  }

  /// Use force, gravity, bodyPosW, parentToSon and motionSubspace (forwardKinematics). Fill
  /// bodyAccB (X_0_i a_0) and jointTorque; f() holds the body forces (body coordinates).
  void inverseStatics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
  {
    const sva::MotionVec<T> a_0(sva::Vector3<T>::Zero(), mbc.gravity);
    for(int i = 0; i < mb.nrBodies(); ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      mbc.bodyAccB[k] = mbc.bodyPosW[k] * a_0;
      f_[k] = mb.body(i).inertia() * mbc.bodyAccB[k] - mbc.bodyPosW[k].dualMul(mbc.force[k]);
    }
    for(int i = mb.nrJoints() - 1; i >= 0; --i)
    {
      const auto k = static_cast<std::size_t>(i);
      const auto & S = mbc.motionSubspace[k];
      for(Eigen::Index c = 0; c < S.cols(); ++c)
        mbc.jointTorque[k][static_cast<std::size_t>(c)] = S.col(c).dot(f_[k].vector());
      if(mb.predecessor(i) >= 0)
        f_[static_cast<std::size_t>(mb.predecessor(i))] += mbc.parentToSon[k].transMul(f_[k]);
    }
  }
  /// Checked variant: std::domain_error on a size mismatch.
  void sInverseStatics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
  {
    checkMatchForce(mb, mbc);
    checkMatchBodyPos(mb, mbc);
    checkMatchParentToSon(mb, mbc);
    checkMatchMotionSubspace(mb, mbc);
    checkMatchBodyAcc(mb, mbc);
    checkMatchJointTorque(mb, mbc);
    inverseStatics(mb, mbc);
  }

  /// Use what inverseStatics uses. Fill jointTorqueDiff(): d tau / dq at rest, the external forces
  /// constant in world coordinates (the inverse dynamics derivative at zero velocity and acceleration).
  void computeTorqueJacobianJoint(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
  {
    MultiBodyConfigTpl<T> rest = mbc;
    for(auto & v : rest.bodyVelB) v = sva::MotionVec<T>::Zero();
    for(auto & v : rest.jointVelocity) v = sva::MotionVec<T>::Zero();
    std::vector<std::vector<T>> zero;
    for(const auto & j : mb.joints()) zero.push_back(j.zeroDof());
    idd_.compute(mb, rest, zero);
    for(int i = 0; i < mb.nrJoints(); ++i)
      jointTorqueDiff_[static_cast<std::size_t>(i)] = idd_.dtauDq().middleRows(mb.jointPosInDof(i), mb.joint(i).dof());
  }
  /// Same, plus the term of RBDyn's jacMomentsAndForces (one matrix per body, 6 x nrDof or empty):
  /// tau_i += S_i^T X_0_i^* sum_{k in subtree(i)} jac_k (RBDyn's sign: jac_k is the derivative of
  /// MINUS the external force on body k, world coordinates at the world origin).
  void computeTorqueJacobianJoint(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                  const std::vector<MatrixX> & jacMomentsAndForces)
  {
    computeTorqueJacobianJoint(mb, mbc);
    std::vector<MatrixX> sub(static_cast<std::size_t>(mb.nrBodies()), MatrixX::Zero(6, mb.nrDof()));
    for(int i = mb.nrBodies() - 1; i >= 0; --i)
    {
      const auto k = static_cast<std::size_t>(i);
      if(jacMomentsAndForces[k].size() > 0) sub[k] += jacMomentsAndForces[k];
      if(mb.parent(i) >= 0) sub[static_cast<std::size_t>(mb.parent(i))] += sub[k];
      // S_i^T X_0_i^* (world-origin wrench derivatives of the subtree)
      jointTorqueDiff_[k] += mbc.motionSubspace[k].transpose() * mbc.bodyPosW[k].dualMul(sub[k]);
    }
  }

  /// Body forces of the last inverseStatics (body coordinates): the force transmitted from λ(i) to i.
  const std::vector<sva::ForceVec<T>> & f() const { return f_; }
  /// Per joint, its rows of d tau / dq (dof x nrDof).
  const std::vector<MatrixX> & jointTorqueDiff() const { return jointTorqueDiff_; }

private:
  std::vector<sva::ForceVec<T>> f_;
  std::vector<MatrixX> jointTorqueDiff_;
  InverseDynamicsDerivativesTpl<T> idd_;
};

using InverseStatics = InverseStaticsTpl<double>;

extern template class InverseStaticsTpl<double>;
extern template class InverseStaticsTpl<long double>;

} // namespace rbd
