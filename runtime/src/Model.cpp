// Explicit instantiations of the model types for double and long double.
#include <rbd/Body.h>
#include <rbd/Joint.h>
#include <rbd/MultiBody.h>
#include <rbd/MultiBodyConfig.h>

namespace rbd
{

const char * jointTypeName(JointType::Type t)
{
  switch(t)
  {
    case JointType::Rev: return "Rev";
    case JointType::Prism: return "Prism";
    case JointType::Spherical: return "Spherical";
    case JointType::Planar: return "Planar";
    case JointType::Cylindrical: return "Cylindrical";
    case JointType::Free: return "Free";
    case JointType::Fixed: return "Fixed";
  }
  return "Unknown";
}

template class JointTpl<double>;
template class JointTpl<long double>;
template class MultiBodyTpl<double>;
template class MultiBodyTpl<long double>;
template struct MultiBodyConfigTpl<double>;
template struct MultiBodyConfigTpl<long double>;

} // namespace rbd
