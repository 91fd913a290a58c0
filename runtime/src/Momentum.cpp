#include <rbd/Momentum.h>

namespace rbd
{

template<typename T>
void CentroidalMomentumMatrixTpl<T>::check(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc) const
{
  const auto n = static_cast<std::size_t>(mb.nrBodies());
  if(weight_.size() != n || cmm_.cols() != mb.nrDof())
    throw std::domain_error("CentroidalMomentumMatrix: the MultiBody does not match");
  if(mbc.bodyPosW.size() != n || mbc.motionSubspace.size() != n || mbc.bodyVelB.size() != n ||
     mbc.jointVelocity.size() != n)
    throw std::domain_error("CentroidalMomentumMatrix: the MultiBodyConfig does not match the MultiBody");
  for(int j = 0; j < mb.nrJoints(); ++j)
    if(mbc.motionSubspace[static_cast<std::size_t>(j)].cols() != mb.joint(j).dof())
      throw std::domain_error("CentroidalMomentumMatrix: motionSubspace of joint '" + mb.joint(j).name() +
                                  "' does not match its dof");
}

template<typename T>
void CentroidalMomentumMatrixTpl<T>::sComputeMatrix(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                                    const Vector3 & com)
{
  check(mb, mbc);
  computeMatrix(mb, mbc, com);
}

template<typename T>
void CentroidalMomentumMatrixTpl<T>::sComputeMatrixDot(const MultiBodyTpl<T> & mb, const MultiBodyConfigTpl<T> & mbc,
                                                       const Vector3 & com, const Vector3 & comDot)
{
  check(mb, mbc);
  computeMatrixDot(mb, mbc, com, comDot);
}

template<typename T>
void CentroidalMomentumMatrixTpl<T>::sComputeMatrixAndMatrixDot(const MultiBodyTpl<T> & mb,
                                                                const MultiBodyConfigTpl<T> & mbc,
                                                                const Vector3 & com, const Vector3 & comDot)
{
  check(mb, mbc);
  computeMatrixAndMatrixDot(mb, mbc, com, comDot);
}

template sva::ForceVec<double> computeCentroidalMomentum(const MultiBodyTpl<double> &,
                                                         const MultiBodyConfigTpl<double> &,
                                                         const sva::Vector3<double> &);
template sva::ForceVec<long double> computeCentroidalMomentum(const MultiBodyTpl<long double> &,
                                                              const MultiBodyConfigTpl<long double> &,
                                                              const sva::Vector3<long double> &);
template sva::ForceVec<double> computeCentroidalMomentumDot(const MultiBodyTpl<double> &,
                                                            const MultiBodyConfigTpl<double> &,
                                                            const sva::Vector3<double> &, const sva::Vector3<double> &);
template sva::ForceVec<long double> computeCentroidalMomentumDot(const MultiBodyTpl<long double> &,
                                                                 const MultiBodyConfigTpl<long double> &,
                                                                 const sva::Vector3<long double> &,
                                                                 const sva::Vector3<long double> &);
template class CentroidalMomentumMatrixTpl<double>;
template class CentroidalMomentumMatrixTpl<long double>;

} // namespace rbd
