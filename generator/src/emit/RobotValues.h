#pragma once
// Template values that describe the robot, shared by the plain and the scene headers: sizes, the
// Body enum, link and dof names.
#include <map>
#include <string>
#include <vector>

#include "../model/RobotModel.h"

namespace rbdgen::emit
{

/// `"a", "b"` with `"` and `\` escaped: a C++ initialiser list of string literals.
std::string quotedList(const std::vector<std::string> & names);

/// nq, nv, nbodies, nframes, body_enum, body_names, dof_names.
std::map<std::string, std::string> robotTemplateValues(const RobotModel & rm);

} // namespace rbdgen::emit
