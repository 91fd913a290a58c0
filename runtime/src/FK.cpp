#include <rbd/Checks.h>
#include <rbd/FK.h>

namespace rbd
{

template<typename T>
void sForwardKinematics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointVector(mb, mbc.q, "q", VectorKind::Param);
  checkMatchBodyVector(mb, mbc.bodyPosW, "bodyPosW");
  checkMatchBodyVector(mb, mbc.jointConfig, "jointConfig");
  checkMatchBodyVector(mb, mbc.parentToSon, "parentToSon");
  forwardKinematics(mb, mbc);
}

template void forwardKinematics(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &);
template void forwardKinematics(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &);
template void sForwardKinematics(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &);
template void sForwardKinematics(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &);

} // namespace rbd
