#include <rbd/Momentum.h>

namespace rbd
{

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
