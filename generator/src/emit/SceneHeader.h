#pragma once
// A scene's part of a header: its effects (SceneEffects.h), the sections only a scene has (state,
// step(), outputs: templates/scene_*.hpp.in) and its coupled API; the assembler is Header.h's.

#include <string>
#include <vector>

#include <rbd/parsers/MimicCoupling.h>
#include <rbd/scene/SceneLoader.h>

#include "../model/RobotModel.h"
#include "Header.h"
#include "SceneEffects.h"

namespace rbdgen::emit
{

/// The effects of a scene on the model built from sceneRobot.robot.
SceneEffects sceneEffects(const RobotModel & rm, const rbd::scene::Scene & scene,
                          const rbd::scene::SceneRobot & sceneRobot);

/// Joints whose subtree is massless and that the scene does not regularise with armature > 0 on
/// every dof: H + diag(armature) is singular when this is not empty.
std::vector<std::string> unregularisedMasslessJoints(const RobotModel & rm, const SceneEffects & fx);

/// Whether the model with effects fx has forward dynamics: no unregularised massless joint and no
/// stacked free joints (H + diag(armature) regular). The header and the batch header both ask this.
bool hasForwardDynamics(const RobotModel & rm, const SceneEffects & fx);

/// "gravity (0, 0, -9.81); velocity terms; damping on 3 dofs; ..." (provenance).
std::string describeEffects(const rbd::scene::Scene & scene, const SceneEffects & fx);

/// Whether the scene's coupled system (mimic joints coupled) has forward dynamics: no stacked free
/// joints, and no joint group that moves only massless links without armature.
bool coupledSceneForwardDynamics(const RobotModel & rm, const SceneEffects & fx, const rbd::parsers::MimicCoupling & c);

/// The spec of a scene's header (its effects, state, step and outputs; derivatives when the scene
/// asks for them). scene and sceneRobot must outlive the spec.
HeaderSpec sceneHeaderSpec(const RobotModel & rm, const rbd::scene::Scene & scene, const rbd::scene::SceneRobot & sceneRobot,
                           const std::string & ns, const std::string & provenance,
                           const rbd::parsers::MimicCoupling & coupling = {});

/// The scene's sections of the header h (emitDynamicsHeader: h holds the common flags and values):
/// state and initial state, wrenches, contacts, inverse dynamics, generalized_bias, forward
/// dynamics (fd), integration, step (and its derivatives) and the outputs.
void sceneSections(HeaderSections & h, const RobotModel & rm, const rbd::scene::Scene & scene,
                   const rbd::scene::SceneRobot & sceneRobot, const SceneEffects & fx, bool fd);

/// The scene's API in the coupled coordinates of a robot with mimic joints (appended after the full
/// model's header, whose namespace is ns::independent): the same template and sections as h, each
/// function a call of independent::'s, projected (templates/mimic_projection.hpp.in).
std::string coupledSceneSections(HeaderSections h, const RobotModel & rm, const rbd::scene::Scene & scene,
                                 const rbd::scene::SceneRobot & sceneRobot, const SceneEffects & fx,
                                 const rbd::parsers::MimicCoupling & coupling, const std::string & ns);

} // namespace rbdgen::emit
