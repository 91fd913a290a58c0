// Explicit instantiations of inverse statics (see rbd/InverseStatics.h).
#include <rbd/InverseStatics.h>

namespace rbd
{

template class InverseStaticsTpl<double>;
template class InverseStaticsTpl<long double>;

} // namespace rbd
