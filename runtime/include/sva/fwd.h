// sva: forward declarations of the spatial algebra classes and their scalar aliases.
#pragma once

#include "EigenTypedef.h"

namespace sva
{

template<class T>
class MotionVec;
template<class T>
class ForceVec;
template<class T>
class RBInertia;
template<class T>
class ABInertia;
template<class T>
class PTransform;

using MotionVecd = MotionVec<double>;
using ForceVecd = ForceVec<double>;
using RBInertiad = RBInertia<double>;
using ABInertiad = ABInertia<double>;
using PTransformd = PTransform<double>;

using MotionVecf = MotionVec<float>;
using ForceVecf = ForceVec<float>;
using RBInertiaf = RBInertia<float>;
using ABInertiaf = ABInertia<float>;
using PTransformf = PTransform<float>;

} // namespace sva
