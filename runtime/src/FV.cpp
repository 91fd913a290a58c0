#include <rbd/Checks.h>
#include <rbd/FV.h>

namespace rbd
{

template<typename T>
void sForwardVelocity(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointVector(mb, mbc.alpha, "alpha", VectorKind::Dof);
  checkMatchBodyVector(mb, mbc.bodyVelB, "bodyVelB");
  checkMatchBodyVector(mb, mbc.bodyVelW, "bodyVelW");
  checkMatchBodyVector(mb, mbc.jointVelocity, "jointVelocity");
  forwardVelocity(mb, mbc);
}

template void forwardVelocity(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &);
template void forwardVelocity(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &);
template void sForwardVelocity(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &);
template void sForwardVelocity(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &);

} // namespace rbd
