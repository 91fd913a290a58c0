#pragma once
// Forward velocity: v_i = X_p_i v_λ(i) + S_i alpha_i (body coordinates).

#include <rbd/MultiBodyConfig.h>

namespace rbd
{

/// Use alpha and the output of forwardKinematics. Fill jointVelocity, bodyVelB and bodyVelW.
template<typename T>
void forwardVelocity(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
{
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & S = mbc.motionSubspace[k];
    Eigen::Matrix<T, 6, 1> vJ = Eigen::Matrix<T, 6, 1>::Zero();
    for(Eigen::Index c = 0; c < S.cols(); ++c) vJ += S.col(c) * mbc.alpha[k][static_cast<std::size_t>(c)];
    mbc.jointVelocity[k] = sva::MotionVec<T>(vJ);
    const int p = mb.parent(i);
    mbc.bodyVelB[k] = p < 0 ? mbc.jointVelocity[k]
                            : mbc.parentToSon[k] * mbc.bodyVelB[static_cast<std::size_t>(p)] + mbc.jointVelocity[k];
    // Same velocity at the body origin, in world-aligned axes.
    mbc.bodyVelW[k] = sva::PTransform<T>(mbc.bodyPosW[k].rotation()).invMul(mbc.bodyVelB[k]);
  }
}

/// Checked variant: throws std::domain_error when alpha does not match the model.
template<typename T>
void sForwardVelocity(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc);

extern template void forwardVelocity(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &);
extern template void forwardVelocity(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &);
extern template void sForwardVelocity(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &);
extern template void sForwardVelocity(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &);

} // namespace rbd
