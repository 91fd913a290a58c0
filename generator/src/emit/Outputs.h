#pragma once
// Writing symbolic results into the emitted function's outputs, and reading precomputed ones back.

#include <string>

#include "../passes/PassContext.h"

namespace rbdgen::emit
{

using namespace rbdgen::cg;

/// `detail::set_pose(<dst>, rotation by rows, translation);`
void writePose(Block & b, const std::string & dst, const Xform & X);
/// `detail::set_motion(<dst>, w, v);`
void writeMotion(Block & b, const std::string & dst, const Motion & m);
/// `<dst>(r, col) = ...` for the non-zero entries of a 6-vector column [top; bottom].
void writeColumn(Block & b, const std::string & dst, int col, const Vec3 & top, const Vec3 & bottom);
/// The output slot of link `body` in an array indexed by Body: `<dst>[detail::at(Body::<ident>)]`.
std::string linkSlot(const RobotModel & rm, const std::string & dst, int body);
/// The world pose of moving frame k read from precomputed kinematics (`kin.frame[k]`).
Xform kinFrame(int k);
/// A symbolic 3-vector `<name>(0..2)` or 6-vector `<name>(0..5)` read from an Eigen object.
Vec3 vec3Var(const std::string & name, int offset = 0);

} // namespace rbdgen::emit
