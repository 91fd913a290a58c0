#include <rbd/ABA.h>
#include <rbd/Checks.h>
#include <rbd/ID.h>

namespace rbd
{

template<typename T>
void ForwardDynamicsABATpl<T>::sForwardDynamics(const MultiBodyTpl<T> & mb, MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointVector(mb, mbc.jointTorque, "jointTorque", VectorKind::Dof);
  checkMatchJointVector(mb, mbc.alphaD, "alphaD", VectorKind::Dof);
  checkMatchBodyVector(mb, mbc.force, "force");
  checkMatchBodyVector(mb, mbc.bodyPosW, "bodyPosW");
  checkMatchBodyVector(mb, mbc.parentToSon, "parentToSon");
  checkMatchBodyVector(mb, mbc.bodyVelB, "bodyVelB");
  checkMatchBodyVector(mb, mbc.bodyAccB, "bodyAccB");
  checkMatchBodyVector(mb, mbc.jointVelocity, "jointVelocity");
  checkMatchMotionSubspace(mb, mbc);
  forwardDynamics(mb, mbc);
}

template class ForwardDynamicsABATpl<double>;
template class ForwardDynamicsABATpl<long double>;

} // namespace rbd
