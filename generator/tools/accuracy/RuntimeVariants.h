#pragma once
// The runtime in double: every studied function timed (set the configuration + forward kinematics
// + forward velocity + the algorithm, as a user of the runtime calls it) and evaluated on the states.

#include <vector>

#include <rbd/parsers/urdf.h>

#include "States.h"
#include "Variants.h"

namespace rbdgen::accuracy
{

std::vector<VariantResult> runRuntimeVariants(const rbd::parsers::ParserResult & robot, const std::vector<State> & states,
                                              bool derivatives = false);

} // namespace rbdgen::accuracy
