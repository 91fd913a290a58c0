#pragma once
// `rbdgen info`: what the loader and the runtime make of a URDF.

#include <ostream>

#include <rbd/parsers/urdf.h>

namespace rbdgen
{

/// Print the kinematic tree (joint type, axis, dof, mass per body), totals, the loader's warnings
/// and the gravity torques at the zero configuration (runtime inverse dynamics).
void printInfo(std::ostream & os, const rbd::parsers::ParserResult & robot);

} // namespace rbdgen
