#pragma once
// step_derivatives of a scene header (templates/scene_step_derivatives.hpp.in): the derivatives of
// one step() of the scene's integrator, A = d x+/d x and B = d x+/d tau in the tangent space, with
// the derivatives of q (+) w emitted per joint (rbd/IntegrationDerivatives.h,
// rbd/scene/StepDerivatives.h of the runtime).

#include <string>

#include <rbd/scene/Scene.h>

#include "../model/RobotModel.h"

namespace rbdgen::emit
{

/// The text inserted after step() in a scene header with <derivatives/> and forward dynamics.
/// wrenches: the scene has external wrenches (an argument of step_derivatives); normalizeLines:
/// step()'s quaternion normalisation lines (RK4; they act on `state`).
std::string sceneStepDerivatives(const RobotModel & rm, rbd::scene::Integrator integrator, bool wrenches,
                                 const std::string & normalizeLines);

} // namespace rbdgen::emit
