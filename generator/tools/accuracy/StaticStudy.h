#pragma once
// The static part of the study: every variant (function x implementation x scalar) against the
// long double reference, grouped by what the caller gets (Pareto front per group).
//
// Stated bounds on the max error (eps: 2^-23 float, 2^-52 double):
//   fk, id, nle, gravity, mass_matrix:  1e4 eps              (double 2.2e-12, float 1.2e-3)
//   fd_aba, fd_crba:                    1e4 eps max(1, cond(H)/1e3), cond(H) the largest over the states
//   id_derivatives [dtau/dq dtau/dalpha]: 1e4 eps
//   fd_derivatives [dalphaD/dq dalphaD/dalpha Minv]: 1e4 eps max(1, cond(H)/1e3)^2
//     (both solvers are only good to about cond(H) eps)
//   "gravity without velocity terms" (gravity_torques against ID(q, alpha, 0)) is a modelling error,
//     not a rounding error: no bound (it is what dropping the velocity terms costs at those speeds).

#include <string>
#include <vector>

#include "ErrorStats.h"
#include "Reference.h"
#include "Variants.h"

namespace rbdgen::accuracy
{

struct StaticRow
{
  std::string group;          ///< forward kinematics, inverse dynamics, bias forces, mass matrix, forward dynamics
  std::string label;          ///< e.g. "generated float fd_aba"
  std::string function, implementation, scalar;
  std::string reference;      ///< reference function it is compared with
  double nsPerCall = 0;
  ErrorStats error;
  double bound = 0;           ///< stated bound on error.max (+inf: none)
  bool pareto = false;        ///< on the Pareto front (ns per call, max error) of its group
};

/// Machine epsilon of a scalar name ("float" or "double").
double scalarEpsilon(const std::string & scalar);

/// Rows for every variant (plus the gravity-as-bias-force rows), Pareto fronts marked per group.
std::vector<StaticRow> evaluateStatic(const std::vector<VariantResult> & variants, const Reference & ref);

} // namespace rbdgen::accuracy
