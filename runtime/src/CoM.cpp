#include <rbd/Checks.h>
#include <rbd/CoM.h>

namespace rbd
{

template<typename T>
void CoMJacobianTpl<T>::check(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, bool needVelocity) const
{
  const auto n = static_cast<std::size_t>(mb.nrBodies());
  if(coeff_.size() != n || jac_.cols() != mb.nrDof())
    throw std::domain_error("CoMJacobian: the MultiBody does not match");
  if(mbc.bodyPosW.size() != n || mbc.motionSubspace.size() != n ||
     (needVelocity && (mbc.bodyVelB.size() != n || mbc.jointVelocity.size() != n || mbc.parentToSon.size() != n)))
    throw std::domain_error("CoMJacobian: the MultiBodyConfig does not match the MultiBody");
  for(int j = 0; j < mb.nrJoints(); ++j)
    if(mbc.motionSubspace[static_cast<std::size_t>(j)].cols() != mb.joint(j).dof())
      throw std::domain_error("CoMJacobian: motionSubspace of joint '" + mb.joint(j).name() +
                                  "' does not match its dof");
}

template<typename T>
const typename CoMJacobianTpl<T>::MatrixX & CoMJacobianTpl<T>::sJacobian(const MultiBodyTpl<T> & mb,
                                                                         const MultiBodyConfigTpl<T> & mbc)
{
  check(mb, mbc, false);
  return jacobian(mb, mbc);
}

template<typename T>
const typename CoMJacobianTpl<T>::MatrixX & CoMJacobianTpl<T>::sJacobianDot(const MultiBodyTpl<T> & mb,
                                                                            const MultiBodyConfigTpl<T> & mbc)
{
  check(mb, mbc, true);
  return jacobianDot(mb, mbc);
}

template<typename T>
typename CoMJacobianTpl<T>::Vector3 CoMJacobianTpl<T>::sVelocity(const MultiBodyTpl<T> & mb,
                                                                 const MultiBodyConfigTpl<T> & mbc) const
{
  check(mb, mbc, true);
  return velocity(mb, mbc);
}

template<typename T>
typename CoMJacobianTpl<T>::Vector3 CoMJacobianTpl<T>::sNormalAcceleration(const MultiBodyTpl<T> & mb,
                                                                           const MultiBodyConfigTpl<T> & mbc)
{
  check(mb, mbc, true);
  return normalAcceleration(mb, mbc);
}

namespace
{
template<typename T>
void checkCoMInputs(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, bool velocity, bool acceleration)
{
  checkMatchBodyVector(mb, mbc.bodyPosW, "bodyPosW");
  if(velocity) checkMatchBodyVector(mb, mbc.bodyVelB, "bodyVelB");
  if(acceleration) checkMatchBodyVector(mb, mbc.bodyAccB, "bodyAccB");
  T M = T(0);
  for(const auto & b : mb.bodies()) M += b.inertia().mass();
  if(!(M > T(0))) throw std::domain_error("CoM: the total mass of the MultiBody is not positive");
}
} // namespace

template<typename T>
sva::Vector3<T> sComputeCoM(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkCoMInputs(mb, mbc, false, false);
  return computeCoM(mb, mbc);
}

template<typename T>
sva::Vector3<T> sComputeCoMVelocity(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkCoMInputs(mb, mbc, true, false);
  return computeCoMVelocity(mb, mbc);
}

template<typename T>
sva::Vector3<T> sComputeCoMAcceleration(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc)
{
  checkCoMInputs(mb, mbc, true, true);
  return computeCoMAcceleration(mb, mbc);
}

template sva::Vector3<double> computeCoM(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &);
template sva::Vector3<long double> computeCoM(const MultiBodyTpl<long double> &,
                                              const MultiBodyConfigTpl<long double> &);
template sva::Vector3<double> computeCoMVelocity(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &);
template sva::Vector3<long double> computeCoMVelocity(const MultiBodyTpl<long double> &,
                                                      const MultiBodyConfigTpl<long double> &);
template sva::Vector3<double> computeCoMAcceleration(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &);
template sva::Vector3<long double> computeCoMAcceleration(const MultiBodyTpl<long double> &,
                                                          const MultiBodyConfigTpl<long double> &);
template sva::Vector3<double> sComputeCoM(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &);
template sva::Vector3<long double> sComputeCoM(const MultiBodyTpl<long double> &,
                                               const MultiBodyConfigTpl<long double> &);
template sva::Vector3<double> sComputeCoMVelocity(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &);
template sva::Vector3<long double> sComputeCoMVelocity(const MultiBodyTpl<long double> &,
                                                       const MultiBodyConfigTpl<long double> &);
template sva::Vector3<double> sComputeCoMAcceleration(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &);
template sva::Vector3<long double> sComputeCoMAcceleration(const MultiBodyTpl<long double> &,
                                                           const MultiBodyConfigTpl<long double> &);
template class CoMJacobianTpl<double>;
template class CoMJacobianTpl<long double>;

template class CoMJacobianDummyTpl<double>;
template class CoMJacobianDummyTpl<long double>;

} // namespace rbd
