#pragma once
// RBDyn's header name for InverseStatics.
#include <rbd/InverseStatics.h>
