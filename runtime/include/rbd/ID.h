#pragma once
// Inverse dynamics: recursive Newton-Euler algorithm (Featherstone, RBDA, table 5.1).
//   a_i = X_p_i a_λ(i) + S_i alphaD_i + v_i x vJ_i             (a_0 = [0; gravity])
//   f_i = I_i a_i + v_i x* I_i v_i - X_0_i^* f_ext_i
//   f_λ(i) += X_p_i^T f_i,   tau_i = S_i^T f_i

#include <vector>

#include <rbd/Checks.h>
#include <rbd/MultiBodyConfig.h>

namespace rbd
{

template<typename T>
class InverseDynamicsTpl
{
public:
  using VectorX = Eigen::Matrix<T, Eigen::Dynamic, 1>;

  InverseDynamicsTpl() = default;
  explicit InverseDynamicsTpl(const MultiBodyTpl<T> & mb)
  : f_(static_cast<std::size_t>(mb.nrBodies()), sva::ForceVec<T>::Zero()),
    acc_(static_cast<std::size_t>(mb.nrBodies()), sva::MotionVec<T>::Zero())
  {
  }

  /// Use alphaD, gravity, force and the outputs of forwardKinematics and forwardVelocity
  /// (parentToSon, bodyPosW, motionSubspace, jointVelocity, bodyVelB).
  /// Fill bodyAccB (INCLUDING the fictitious base acceleration [0; gravity], as RBDyn) and
  /// jointTorque; f() holds the body forces (body coordinates) after the call.
  void inverseDynamics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
  {
    rnea(mb, mbc, true, mbc.bodyAccB);
    for(int i = 0; i < mb.nrJoints(); ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      // tau_i = S_i^T f_i
      const Eigen::Matrix<T, 6, 1> f = f_[k].vector();
      for(Eigen::Index c = 0; c < mbc.motionSubspace[k].cols(); ++c)
        mbc.jointTorque[k][static_cast<std::size_t>(c)] = mbc.motionSubspace[k].col(c).dot(f);
    }
  }

  /// Checked variant: throws std::domain_error on a size mismatch.
  void sInverseDynamics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc);

  /// Nonlinear effects C (size nrDof): inverse dynamics with alphaD = 0 (Coriolis, centrifugal,
  /// gravity and external forces). Use gravity, force and the outputs of FK and FV; mbc is not
  /// modified (f() is overwritten).
  void nonLinearEffects(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, Eigen::Ref<VectorX> C)
  {
    rnea(mb, mbc, false, acc_);
    for(int i = 0; i < mb.nrJoints(); ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      const auto & S = mbc.motionSubspace[k];
      C.segment(mb.jointPosInDof(i), S.cols()).noalias() = S.transpose() * f_[k].vector();
    }
  }

  /// Body forces f_i (body coordinates) of the last call.
  const std::vector<sva::ForceVec<T>> & f() const { return f_; }

private:
  /// Forward pass (accelerations into acc, forces into f_) and backward force accumulation.
  void rnea(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, bool withAlphaD,
            std::vector<sva::MotionVec<T>> & acc)
  {
    const std::size_t n = static_cast<std::size_t>(mb.nrBodies());
    if(f_.size() != n) f_.assign(n, sva::ForceVec<T>::Zero());
    if(acc.size() != n) acc.assign(n, sva::MotionVec<T>::Zero());
    const sva::MotionVec<T> a_0(sva::Vector3<T>::Zero(), mbc.gravity);
    for(int i = 0; i < mb.nrJoints(); ++i)
    {
      const auto k = static_cast<std::size_t>(i);
      const int p = mb.parent(i);
      const auto & v_i = mbc.bodyVelB[k];
      // a_i = X_p_i a_p + S alphaD + v_i x vJ
      sva::MotionVec<T> a = mbc.parentToSon[k] * (p < 0 ? a_0 : acc[static_cast<std::size_t>(p)]) +
                            v_i.cross(mbc.jointVelocity[k]);
      if(withAlphaD)
      {
        const auto & S = mbc.motionSubspace[k];
        Eigen::Matrix<T, 6, 1> aJ = Eigen::Matrix<T, 6, 1>::Zero();
        for(Eigen::Index c = 0; c < S.cols(); ++c) aJ += S.col(c) * mbc.alphaD[k][static_cast<std::size_t>(c)];
        a += sva::MotionVec<T>(aJ);
      }
      acc[k] = a;
      // f_i = I a_i + v_i x* (I v_i) - X_0_i^* f_ext (external force: world coordinates, world origin)
      const auto & I = mb.body(i).inertia();
      f_[k] = I * a + v_i.crossDual(I * v_i) - mbc.bodyPosW[k].dualMul(mbc.force[k]);
    }
    // f_p += X_p_i^T f_i
    for(int i = mb.nrJoints() - 1; i >= 0; --i)
    {
      const auto k = static_cast<std::size_t>(i);
      const int p = mb.parent(i);
      if(p >= 0) f_[static_cast<std::size_t>(p)] += mbc.parentToSon[k].transMul(f_[k]);
    }
  }

  std::vector<sva::ForceVec<T>> f_;
  std::vector<sva::MotionVec<T>> acc_; ///< accelerations of nonLinearEffects (mbc untouched)
};

using InverseDynamics = InverseDynamicsTpl<double>;

extern template class InverseDynamicsTpl<double>;
extern template class InverseDynamicsTpl<long double>;

} // namespace rbd
