#pragma once
// Scene file -> Scene (tinyxml2), Scene -> robot with the scene's joints locked (loader/).

#include <stdexcept>
#include <string>
#include <vector>

#include <rbd/parsers/urdf.h>

#include "Scene.h"

namespace rbd::scene
{

/// One-line error: "<file>:<line>: <element> '<name>': <reason>".
class SceneError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Parse a scene file (unknown elements/attributes, unknown names, impossible values: SceneError).
/// Joint/body names are checked against the robot (the URDF is loaded).
Scene loadScene(const std::string & path);
/// Same, from text; sourceName stands for the file, baseDir resolves the relative URDF path.
Scene loadSceneString(const std::string & xml, const std::string & sourceName, const std::string & baseDir);

/// The robot of a scene, ready for the runtime and the generator.
struct SceneRobot
{
  /// URDF loaded with the scene's base options; locked joints replaced by fixed joints at their
  /// held position (so they are gone from q and alpha and their bodies merge into the parent).
  rbd::parsers::ParserResult robot;
  /// Per velocity coordinate of robot.mb (size nv): the joint effects of the scene.
  Eigen::VectorXd damping, friction, armature;
  /// Index in robot.mb of each contact's body / each external wrench's body (scene order).
  std::vector<int> contactBodies, wrenchBodies;
};

SceneRobot loadSceneRobot(const Scene & scene);

} // namespace rbd::scene
