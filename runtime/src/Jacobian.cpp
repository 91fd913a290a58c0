#include <rbd/Jacobian.h>

namespace rbd
{

template void computeNormalAccB(const MultiBodyTpl<double> &, const MultiBodyConfigTpl<double> &,
                                std::vector<sva::MotionVec<double>> &);
template void computeNormalAccB(const MultiBodyTpl<long double> &, const MultiBodyConfigTpl<long double> &,
                                std::vector<sva::MotionVec<long double>> &);
template class JacobianTpl<double>;
template class JacobianTpl<long double>;

} // namespace rbd
