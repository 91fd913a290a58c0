#pragma once
// `rbdgen info`: what the loader and the runtime make of a URDF.

#include <ostream>
#include <string>

#include <rbd/parsers/urdf.h>

namespace rbdgen
{

/// Print the kinematic tree (joint type, axis, dof, mass per body), totals, the loader's warnings,
/// the mass matrix checks (model/MassMatrixChecks.h: M, L, the smallest effective inertia ratio and
/// its dof, the warnings `rbdgen generate` gives; source names the file in them) and the gravity
/// torques at the zero configuration (runtime inverse dynamics).
void printInfo(std::ostream & os, const rbd::parsers::ParserResult & robot, const std::string & source);

} // namespace rbdgen
