// Explicit instantiations of the constant-acceleration integration (see rbd/NumericalIntegration.h).
#include <rbd/NumericalIntegration.h>

namespace rbd
{

template void integration<double>(const MultiBodyTpl<double> &, MultiBodyConfigTpl<double> &, double, double);
template void integration<long double>(const MultiBodyTpl<long double> &, MultiBodyConfigTpl<long double> &,
                                       long double, long double);

} // namespace rbd
