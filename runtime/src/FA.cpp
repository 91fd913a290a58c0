#include <rbd/Checks.h>
#include <rbd/FA.h>

namespace rbd
{

template<typename T>
void sForwardAcceleration(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc, const sva::MotionVec<T> & A_0)
{
  checkMatchJointVector(mb, mbc.alphaD, "alphaD", VectorKind::Dof);
  checkMatchBodyVector(mb, mbc.bodyAccB, "bodyAccB");
  forwardAcceleration(mb, mbc, A_0);
}

template void forwardAcceleration(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &, const sva::MotionVec<double> &);
template void forwardAcceleration(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &, const sva::MotionVec<long double> &);
template void sForwardAcceleration(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &, const sva::MotionVec<double> &);
template void sForwardAcceleration(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &, const sva::MotionVec<long double> &);

} // namespace rbd
