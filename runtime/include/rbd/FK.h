#pragma once
// Forward kinematics: X_0_i = X_j(q_i) X_T,i X_0_λ(i).

#include <rbd/MultiBodyConfig.h>

namespace rbd
{

/// Use q. Fill jointConfig (X_j), motionSubspace (S(q)), parentToSon (X_p_i) and bodyPosW (X_0_i).
template<typename T>
void forwardKinematics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
{
  for(int i = 0; i < mb.nrJoints(); ++i)
  {
    const auto k = static_cast<std::size_t>(i);
    const auto & joint = mb.joint(i);
    mbc.jointConfig[k] = joint.pose(mbc.q[k]);
    if(!joint.constantMotionSubspace()) mbc.motionSubspace[k] = joint.motionSubspace(mbc.q[k]);
    // X_p_i = X_j X_T
    mbc.parentToSon[k] = mbc.jointConfig[k] * mb.transform(i);
    const int p = mb.parent(i);
    mbc.bodyPosW[k] = p < 0 ? mbc.parentToSon[k] : mbc.parentToSon[k] * mbc.bodyPosW[static_cast<std::size_t>(p)];
  }
}

/// Checked variant: throws std::domain_error when q does not match the model.
template<typename T>
void sForwardKinematics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc);

extern template void forwardKinematics(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &);
extern template void forwardKinematics(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &);
extern template void sForwardKinematics(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &);
extern template void sForwardKinematics(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &);

} // namespace rbd
