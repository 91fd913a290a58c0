#pragma once
// Forward acceleration: a_i = X_p_i a_λ(i) + S_i alphaD_i + v_i x (S_i alpha_i) (body coordinates).

#include <rbd/MultiBodyConfig.h>

namespace rbd
{

/// Use alphaD and the outputs of forwardKinematics and forwardVelocity. Fill bodyAccB (without
/// gravity). @param A_0 acceleration of the world (e.g. [0; gravity] to include gravity).
template<typename T>
void forwardAcceleration(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc,
                         const sva::MotionVec<T> & A_0 = sva::MotionVec<T>::Zero())
{
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & S = mbc.motionSubspace[k];
    Eigen::Matrix<T, 6, 1> aJ = Eigen::Matrix<T, 6, 1>::Zero();
    for(Eigen::Index c = 0; c < S.cols(); ++c) aJ += S.col(c) * mbc.alphaD[k][static_cast<std::size_t>(c)];
    const int p = mb.parent(i);
    const sva::MotionVec<T> a_p = p < 0 ? A_0 : mbc.bodyAccB[static_cast<std::size_t>(p)];
    mbc.bodyAccB[k] = mbc.parentToSon[k] * a_p + sva::MotionVec<T>(aJ) + mbc.bodyVelB[k].cross(mbc.jointVelocity[k]);
  }
}

/// Checked variant: throws std::domain_error when alphaD does not match the model.
template<typename T>
void sForwardAcceleration(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc,
                          const sva::MotionVec<T> & A_0 = sva::MotionVec<T>::Zero());

extern template void forwardAcceleration(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &, const sva::MotionVec<double> &);
extern template void forwardAcceleration(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &, const sva::MotionVec<long double> &);
extern template void sForwardAcceleration(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &, const sva::MotionVec<double> &);
extern template void sForwardAcceleration(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &, const sva::MotionVec<long double> &);

} // namespace rbd
