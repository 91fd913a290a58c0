#include <rbd/Checks.h>
#include <rbd/FD.h>

namespace rbd
{

template<typename T>
void ForwardDynamicsTpl<T>::sForwardDynamics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointVector(mb, mbc.jointTorque, "jointTorque", VectorKind::Dof);
  checkMatchJointVector(mb, mbc.alphaD, "alphaD", VectorKind::Dof);
  checkMatchBodyVector(mb, mbc.force, "force");
  checkMatchBodyVector(mb, mbc.bodyPosW, "bodyPosW");
  checkMatchBodyVector(mb, mbc.parentToSon, "parentToSon");
  checkMatchBodyVector(mb, mbc.bodyVelB, "bodyVelB");
  checkMatchBodyVector(mb, mbc.jointVelocity, "jointVelocity");
  checkMatchMotionSubspace(mb, mbc);
  forwardDynamics(mb, mbc);
}

template class ForwardDynamicsTpl<double>;
template class ForwardDynamicsTpl<long double>;

} // namespace rbd
