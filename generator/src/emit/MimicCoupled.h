#pragma once
// The coupled API of a robot with mimic joints (templates/mimic_coupled.hpp.in): the plain
// header's functions in the coupled coordinates, on top of the full model emitted in
// `<namespace>::independent`.
#include <map>
#include <string>
#include <vector>

#include <rbd/parsers/MimicCoupling.h>

#include "../model/RobotModel.h"

namespace rbdgen::emit
{

/// The joints of the full model that keep the coupled mass matrix singular: the massless-subtree
/// joints whose coupled coordinate moves only massless links (every joint that follows it massless too).
std::vector<std::string> coupledMasslessJoints(const RobotModel & rm, const rbd::parsers::MimicCoupling & c);

/// Whether the coupled system has forward dynamics (its mass matrix is regular).
bool coupledForwardDynamics(const RobotModel & rm, const rbd::parsers::MimicCoupling & c);

/// expand_configuration, expand_tangent, project_columns/tangent/matrix and the dense L D L^T of
/// the coupled mass matrix (templates/mimic_projection.hpp.in), for a namespace whose Config and
/// Tangent are the coupled ones and whose `independent` is the full model.
std::string mimicProjection(const rbd::parsers::MimicCoupling & c);

/// The template values every coupled section shows: namespace, nq, nv, dof_names, nmimic,
/// mimic_couplings and projection (mimicProjection).
std::map<std::string, std::string> coupledTemplateValues(const rbd::parsers::MimicCoupling & c, const std::string & ns);

/// The model restricted to the coupled coordinates: the mimic joints left out, the other joints'
/// q and alpha offsets those of the coupled system (for per-joint code such as integrate()).
/// Only the joints and sizes are meaningful (the links and inertias are the full model's).
RobotModel coupledView(const RobotModel & rm, const rbd::parsers::MimicCoupling & c);

/// The coupled section, appended after the full model's header (whose namespace is ns::independent).
std::string mimicCoupledSection(const rbd::parsers::MimicCoupling & c, const std::string & ns, bool forwardDynamics,
                                bool derivatives);

} // namespace rbdgen::emit
