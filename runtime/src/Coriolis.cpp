// Explicit instantiations of the Coriolis matrix (see rbd/Coriolis.h).
#include <rbd/Coriolis.h>

namespace rbd
{

template class CoriolisTpl<double>;
template class CoriolisTpl<long double>;

} // namespace rbd
