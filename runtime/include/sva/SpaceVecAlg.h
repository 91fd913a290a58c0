// sva: spatial vector algebra (Featherstone, "Rigid Body Dynamics Algorithms", appendix A),
// header-only, templated on the scalar type. Umbrella header.
#pragma once

#include "EigenTypedef.h"
#include "fwd.h"

#include "ABInertia.h"
#include "AdmittanceVec.h"
#include "EigenUtility.h"
#include "ForceVec.h"
#include "ImpedanceVec.h"
#include "MathFunc.h"
#include "MotionVec.h"
#include "PTransform.h"
#include "RBInertia.h"

#include "Conversions.h"
