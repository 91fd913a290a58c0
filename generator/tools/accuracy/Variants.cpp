#include "Variants.h"

#include <map>

namespace rbdgen::accuracy
{

const std::vector<std::string> & studiedFunctions()
{
  static const std::vector<std::string> f = {"fk", "id", "nle", "gravity", "mass_matrix", "fd_aba", "fd_crba"};
  return f;
}

std::string describeFunction(const std::string & function)
{
  static const std::map<std::string, std::string> d = {
      {"fk", "forward kinematics: world pose of every link"},
      {"id", "inverse dynamics, all terms: tau = ID(q, alpha, alphaD)"},
      {"nle", "inverse dynamics without acceleration: Coriolis, centrifugal, gravity"},
      {"gravity", "inverse dynamics without velocity terms: gravity torques"},
      {"mass_matrix", "joint-space inertia matrix H(q)"},
      {"fd_aba", "forward dynamics, articulated-body algorithm"},
      {"fd_crba", "forward dynamics, mass matrix + factorisation"},
  };
  const auto it = d.find(function);
  return it == d.end() ? function : it->second;
}

} // namespace rbdgen::accuracy
