#include <rbd/ZMP.h>

namespace rbd
{

template sva::Vector3<double> computeCentroidalZMP(const MultiBodyConfigTpl<double> &, const sva::Vector3<double> &,
                                                   const sva::Vector3<double> &, double);
template sva::Vector3<long double> computeCentroidalZMP(const MultiBodyConfigTpl<long double> &,
                                                        const sva::Vector3<long double> &,
                                                        const sva::Vector3<long double> &, long double);
template sva::Vector3<double> computeCentroidalZMP(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &,
                                                   const sva::Vector3<double> &, const sva::ForceVec<double> &,
                                                   double);
template sva::Vector3<long double> computeCentroidalZMP(const MultiBodyTpl<long double> &,
                                                        const MultiBodyConfigTpl<long double> &,
                                                        const sva::Vector3<long double> &,
                                                        const sva::ForceVec<long double> &, long double);

} // namespace rbd
