#include <rbd/Checks.h>
#include <rbd/ID.h>

namespace rbd
{

template<typename T>
void InverseDynamicsTpl<T>::sInverseDynamics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointVector(mb, mbc.alphaD, "alphaD", VectorKind::Dof);
  checkMatchJointVector(mb, mbc.jointTorque, "jointTorque", VectorKind::Dof);
  checkMatchBodyVector(mb, mbc.force, "force");
  checkMatchBodyVector(mb, mbc.bodyPosW, "bodyPosW");
  checkMatchBodyVector(mb, mbc.parentToSon, "parentToSon");
  checkMatchBodyVector(mb, mbc.bodyVelB, "bodyVelB");
  checkMatchBodyVector(mb, mbc.bodyAccB, "bodyAccB");
  checkMatchBodyVector(mb, mbc.jointVelocity, "jointVelocity");
  checkMatchMotionSubspace(mb, mbc);
  inverseDynamics(mb, mbc);
}

template class InverseDynamicsTpl<double>;
template class InverseDynamicsTpl<long double>;

} // namespace rbd
