#pragma once
// The functions compared by the accuracy study and the result of one variant (function x
// implementation x scalar). Outputs are flattened the same way by every implementation:
//   fk           per link: world pose rotation (3 x 3, column-major, maps world into link coordinates)
//                then the link origin in world coordinates (3): 12 values per link
//   id           inverse_dynamics(q, alpha, alphaD)            (all terms)
//   nle          nonlinear_effects(q, alpha) = ID(q, alpha, 0) (velocity and gravity terms)
//   gravity      gravity_torques(q) = ID(q, 0, 0)              (no velocity terms)
//   mass_matrix  H(q), column-major
//   fd_aba       forward dynamics by the articulated-body algorithm
//   fd_crba      forward dynamics by the mass matrix and its factorisation

#include <string>
#include <vector>

#include <Eigen/Core>

namespace rbdgen::accuracy
{

/// The functions, in report order (their names are those of the driver and the CSV).
const std::vector<std::string> & studiedFunctions();

/// One-line description of a function for the report.
std::string describeFunction(const std::string & function);

struct VariantResult
{
  std::string function;       ///< one of studiedFunctions()
  std::string implementation; ///< "generated" or "runtime"
  std::string scalar;         ///< "float" or "double"
  double nsPerCall = 0;       ///< median over runs of the time per call
  std::vector<Eigen::VectorXd> outputs; ///< one per state, flattened as above, in double
};

} // namespace rbdgen::accuracy
