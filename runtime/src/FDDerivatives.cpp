#include <rbd/Checks.h>
#include <rbd/FDDerivatives.h>

namespace rbd
{

template<typename T>
void ForwardDynamicsDerivativesTpl<T>::sForwardDynamicsDerivatives(const MultiBodyTpl<T> & mb,
                                                                   const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointVector(mb, mbc.jointTorque, "jointTorque", VectorKind::Dof);
  checkMatchBodyVector(mb, mbc.force, "force");
  checkMatchBodyVector(mb, mbc.bodyPosW, "bodyPosW");
  checkMatchBodyVector(mb, mbc.parentToSon, "parentToSon");
  checkMatchBodyVector(mb, mbc.bodyVelB, "bodyVelB");
  checkMatchBodyVector(mb, mbc.jointVelocity, "jointVelocity");
  checkMatchMotionSubspace(mb, mbc);
  forwardDynamicsDerivatives(mb, mbc);
}

template class ForwardDynamicsDerivativesTpl<double>;
template class ForwardDynamicsDerivativesTpl<long double>;

} // namespace rbd
