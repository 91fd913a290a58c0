#include <rbd/Jacobian.h>

namespace rbd
{

// --- checked variants ------------------------------------------------------------------------

template<typename T>
void JacobianTpl<T>::checkModel(const MultiBodyTpl<T> & mb) const
{
  auto same = [&](int i, const std::string & name) { return i >= 0 && i < mb.nrBodies() && mb.body(i).name() == name; };
  bool ok = same(body_, bodyName_);
  for(int j : jointsPath_) ok = ok && j < mb.nrJoints();
  if(!ok) throw std::domain_error("Jacobian of body '" + bodyName_ + "': the MultiBody does not match");
}

template<typename T>
void JacobianTpl<T>::check(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc, bool needVelocity) const
{
  checkModel(mb);
  auto bodyVec = [&](std::size_t n, const char * name) {
    if(static_cast<int>(n) != mb.nrBodies())
      throw std::domain_error(std::string("Jacobian: ") + name + " has " + std::to_string(n) + " entries, model has " +
                              std::to_string(mb.nrBodies()) + " bodies");
  };
  bodyVec(mbc.bodyPosW.size(), "bodyPosW");
  bodyVec(mbc.motionSubspace.size(), "motionSubspace");
  if(needVelocity)
  {
    bodyVec(mbc.bodyVelB.size(), "bodyVelB");
    bodyVec(mbc.jointVelocity.size(), "jointVelocity");
    bodyVec(mbc.parentToSon.size(), "parentToSon");
  }
  for(int j : jointsPath_)
    if(mbc.motionSubspace[static_cast<std::size_t>(j)].cols() != mb.joint(j).dof())
      throw std::domain_error("Jacobian: motionSubspace of joint '" + mb.joint(j).name() + "' does not match its dof");
}

template<typename T>
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::sJacobian(const MultiBodyTpl<T> & mb,
                                                                   const MultiBodyConfigTpl<T> & mbc,
                                                                   const PTransformT & X_0_p)
{
  check(mb, mbc, false);
  return jacobian(mb, mbc, X_0_p);
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
const typename JacobianTpl<T>::MatrixX & JacobianTpl<T>::sVectorBodyJacobian(const MultiBodyTpl<T> & mb,
                                                                             const MultiBodyConfigTpl<T> & mbc,
                                                                             const Vector3 & vec)
{
  check(mb, mbc, false);
  return vectorBodyJacobian(mb, mbc, vec);
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
                                        const Vector3 & point, MatrixX & res) const
{
  if(jac.rows() != 6) throw std::domain_error("translateJacobian: the Jacobian must have 6 rows");
  if(body_ >= static_cast<int>(mbc.bodyPosW.size()) || refBody_ >= static_cast<int>(mbc.bodyPosW.size()))
    throw std::domain_error("translateJacobian: bodyPosW does not match the Jacobian's model");
  translateJacobian(jac, mbc, point, res);
}

template<typename T>
void JacobianTpl<T>::sFullJacobian(const MultiBodyTpl<T> & mb, const Eigen::Ref<const MatrixX> & jac,
                                   MatrixX & res) const
{
  if(jac.cols() != dof_)
    throw std::domain_error("fullJacobian: the Jacobian has " + std::to_string(jac.cols()) + " columns, expected " +
                            std::to_string(dof_));
  checkModel(mb);
  fullJacobian(mb, jac, res);
}

template<typename T>
MultiBodyTpl<T> JacobianTpl<T>::sSubMultiBody(const MultiBodyTpl<T> & mb) const
{
  checkModel(mb);
  return subMultiBody(mb);
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::sVelocity(const MultiBodyTpl<T> & mb,
                                                              const MultiBodyConfigTpl<T> & mbc) const
{
  check(mb, mbc, true);
  return velocity(mb, mbc);
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::sBodyVelocity(const MultiBodyTpl<T> & mb,
                                                                  const MultiBodyConfigTpl<T> & mbc) const
{
  check(mb, mbc, true);
  return bodyVelocity(mb, mbc);
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::sNormalAcceleration(const MultiBodyTpl<T> & mb,
                                                                        const MultiBodyConfigTpl<T> & mbc) const
{
  check(mb, mbc, true);
  return normalAcceleration(mb, mbc);
}

template<typename T>
typename JacobianTpl<T>::MotionVecT JacobianTpl<T>::sBodyNormalAcceleration(const MultiBodyTpl<T> & mb,
                                                                            const MultiBodyConfigTpl<T> & mbc) const
{
  check(mb, mbc, true);
  return bodyNormalAcceleration(mb, mbc);
}

template void computeNormalAccB(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &,
                                std::vector<sva::MotionVec<double>> &);
template void computeNormalAccB(const MultiBodyTpl<long double> &, const MultiBodyConfigTpl<long double> &,
                                std::vector<sva::MotionVec<long double>> &);
template class JacobianTpl<double>;
template class JacobianTpl<long double>;

} // namespace rbd
