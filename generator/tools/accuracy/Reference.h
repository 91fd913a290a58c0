#pragma once
// The accuracy reference: the runtime evaluated in long double (MultiBody::cast<long double>) on
// the study's states, for every studied function, rounded to double only at the end.

#include <map>
#include <string>
#include <vector>

#include <rbd/parsers/urdf.h>

#include "States.h"

namespace rbdgen::accuracy
{

struct Reference
{
  std::map<std::string, std::vector<Eigen::VectorXd>> outputs; ///< function -> one output per state
  std::vector<double> condH; ///< condition number of H per state (eigenvalues in long double; inf if singular)
};

/// derivatives: also id_derivatives [dtau/dq, dtau/dalpha] and fd_derivatives [dalphaD/dq, dalphaD/dalpha, Minv]
/// (column-major blocks side by side, rbd/IDDerivatives.h and FDDerivatives.h in long double).
Reference computeReference(const rbd::parsers::ParserResult & robot, const std::vector<State> & states,
                           bool derivatives = false);

/// World-to-link transforms of the MultiBody bodies in the URDF link frames (fk layout, see Variants.h).
Eigen::VectorXd flattenPoses(const rbd::parsers::ParserResult & robot, const std::vector<sva::PTransformd> & bodyPosW);

} // namespace rbdgen::accuracy
