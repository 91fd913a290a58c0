// ConfigConverter: checked conversion and explicit instantiations (see rbd/ConfigConverter.h).
#include <rbd/Checks.h>
#include <rbd/ConfigConverter.h>

namespace rbd
{

template<typename T>
void ConfigConverterTpl<T>::sConvert(const MultiBodyConfigTpl<T> & mbc1, MultiBodyConfigTpl<T> & mbc2) const
{
  for(const auto * p : {&mbc1, static_cast<const MultiBodyConfigTpl<T> *>(&mbc2)})
  {
    const MultiBodyTpl<T> & mb = p == &mbc1 ? mb1_ : mb2_;
    checkMatchJointVector(mb, p->q, "q", VectorKind::Param);
    checkMatchJointVector(mb, p->alpha, "alpha", VectorKind::Dof);
    checkMatchJointVector(mb, p->alphaD, "alphaD", VectorKind::Dof);
    checkMatchJointVector(mb, p->jointTorque, "jointTorque", VectorKind::Dof);
    checkMatchBodyVector(mb, p->force, "force");
  }
  convert(mbc1, mbc2);
}

template class ConfigConverterTpl<double>;
template class ConfigConverterTpl<long double>;

} // namespace rbd
