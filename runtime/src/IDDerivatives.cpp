#include <rbd/Checks.h>
#include <rbd/ID.h>
#include <rbd/IDDerivatives.h>

namespace rbd
{

template<typename T>
void InverseDynamicsDerivativesTpl<T>::sInverseDynamicsDerivatives(const MultiBodyTpl<T> & mb,
                                                                   const MultiBodyConfigTpl<T> & mbc)
{
  checkMatchJointVector(mb, mbc.alphaD, "alphaD", VectorKind::Dof);
  checkMatchBodyVector(mb, mbc.force, "force");
  checkMatchBodyVector(mb, mbc.bodyPosW, "bodyPosW");
  checkMatchBodyVector(mb, mbc.parentToSon, "parentToSon");
  checkMatchBodyVector(mb, mbc.bodyVelB, "bodyVelB");
  checkMatchBodyVector(mb, mbc.jointVelocity, "jointVelocity");
  checkMatchMotionSubspace(mb, mbc);
  inverseDynamicsDerivatives(mb, mbc);
}

template class InverseDynamicsDerivativesTpl<double>;
template class InverseDynamicsDerivativesTpl<long double>;

} // namespace rbd
