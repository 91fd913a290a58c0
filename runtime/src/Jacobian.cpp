#include <rbd/Jacobian.h>

namespace rbd
{

// --- checked variants ------------------------------------------------------------------------

template<typename T>
void JacobianTpl<T>::check(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, bool needVelocity) const
{
  if(body_ < 0 || body_ >= mb.nrBodies() || mb.body(body_).name() != bodyName_)
    throw std::invalid_argument("Jacobian of body '" + bodyName_ + "': the MultiBody does not match");
  auto bodyVec = [&](std::size_t n, const char * name) {
    if(static_cast<int>(n) != mb.nrBodies())
      throw std::invalid_argument(std::string("Jacobian: ") + name + " has " + std::to_string(n) +
                                  " entries, model has " + std::to_string(mb.nrBodies()) + " bodies");
  };
  bodyVec(mbc.bodyPosW.size(), "bodyPosW");
  bodyVec(mbc.motionSubspace.size(), "motionSubspace");
  if(needVelocity)
  {
    bodyVec(mbc.bodyVelB.size(), "bodyVelB");
    bodyVec(mbc.jointVelocity.size(), "jointVelocity");
  }
  for(int j : jointsPath_)
    if(mbc.motionSubspace[static_cast<std::size_t>(j)].cols() != mb.joint(j).dof())
      throw std::invalid_argument("Jacobian: motionSubspace of joint '" + mb.joint(j).name() +
                                  "' does not match its dof");
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::sJacobian(const MultiBodyTpl<T> & mb,
                                                                   const MultiBodyConfigTpl<T> & mbc)
{
  check(mb, mbc, false);
  return jacobian(mb, mbc);
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::sBodyJacobian(const MultiBodyTpl<T> & mb,
                                                                       const MultiBodyConfigTpl<T> & mbc)
{
  check(mb, mbc, false);
  return bodyJacobian(mb, mbc);
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::sVectorJacobian(const MultiBodyTpl<T> & mb,
                                                                         const MultiBodyConfigTpl<T> & mbc,
                                                                         const Vector3 & vec)
{
  check(mb, mbc, false);
  return vectorJacobian(mb, mbc, vec);
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::sBodyVectorJacobian(const MultiBodyTpl<T> & mb,
                                                                             const MultiBodyConfigTpl<T> & mbc,
                                                                             const Vector3 & vec)
{
  check(mb, mbc, false);
  return bodyVectorJacobian(mb, mbc, vec);
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::sJacobianDot(const MultiBodyTpl<T> & mb,
                                                                      const MultiBodyConfigTpl<T> & mbc)
{
  check(mb, mbc, true);
  return jacobianDot(mb, mbc);
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::sBodyJacobianDot(const MultiBodyTpl<T> & mb,
                                                                          const MultiBodyConfigTpl<T> & mbc)
{
  check(mb, mbc, true);
  return bodyJacobianDot(mb, mbc);
}

template<typename T>
void JacobianTpl<T>::sTranslateJacobian(const Eigen::Ref<const MatrixX> & jac, const MultiBodyConfigTpl<T> & mbc,
                                        const Vector3 & offset, MatrixX & res) const
{
  if(jac.rows() != 6) throw std::invalid_argument("translateJacobian: the Jacobian must have 6 rows");
  translateJacobian(jac, mbc, offset, res);
}

template<typename T>
void JacobianTpl<T>::sFullJacobian(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac,
                                   MatrixX & res) const
{
  if(jac.cols() != dof_)
    throw std::invalid_argument("fullJacobian: the Jacobian has " + std::to_string(jac.cols()) + " columns, expected " +
                                std::to_string(dof_));
  for(int j : jointsPath_)
    if(j >= mb.nrJoints()) throw std::invalid_argument("fullJacobian: the MultiBody does not match");
  fullJacobian(mb, jac, res);
}

template void computeNormalAccB(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &,
                                std::vector<sva::MotionVec<double>> &);
template void computeNormalAccB(const MultiBodyTpl<long double> &, const MultiBodyConfigTpl<long double> &,
                                std::vector<sva::MotionVec<long double>> &);
template class JacobianTpl<double>;
template class JacobianTpl<long double>;

} // namespace rbd
