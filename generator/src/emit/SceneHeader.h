#pragma once
// The header of a scene: the plain API specialised to the scene's effects (SceneEffects.h), its
// outputs and step(), from templates/scene_*.hpp.in.

#include <string>
#include <vector>

#include <rbd/parsers/MimicCoupling.h>
#include <rbd/scene/SceneLoader.h>

#include "../model/RobotModel.h"
#include "SceneEffects.h"

namespace rbdgen::emit
{

/// The effects of a scene on the model built from sceneRobot.robot.
SceneEffects sceneEffects(const RobotModel & rm, const rbd::scene::Scene & scene,
                          const rbd::scene::SceneRobot & sceneRobot);

/// Joints whose subtree is massless and that the scene does not regularise with armature > 0 on
/// every dof: H + diag(armature) is singular when this is not empty.
std::vector<std::string> unregularisedMasslessJoints(const RobotModel & rm, const SceneEffects & fx);

/// "gravity (0, 0, -9.81); velocity terms; damping on 3 dofs; ..." (provenance).
std::string describeEffects(const rbd::scene::Scene & scene, const SceneEffects & fx);

/// Whether the scene's coupled system (mimic joints coupled) has forward dynamics: no stacked free
/// joints, and no joint group that moves only massless links without armature.
bool coupledSceneForwardDynamics(const RobotModel & rm, const SceneEffects & fx, const rbd::parsers::MimicCoupling & c);

/// The whole header text; provenance: the lines that open it (comments). A non-empty coupling
/// (mimic joints) emits the full model in ns::independent and the scene's API in the coupled
/// coordinates in ns (the same functions, projected: templates/mimic_projection.hpp.in); otherwise
/// ns::independent is an alias of ns.
std::string emitSceneHeader(const RobotModel & rm, const rbd::scene::Scene & scene,
                            const rbd::scene::SceneRobot & sceneRobot, const std::string & ns,
                            const std::string & provenance, const rbd::parsers::MimicCoupling & coupling = {});

} // namespace rbdgen::emit
