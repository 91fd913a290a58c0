#pragma once
// A scene whose robot is built in code, because URDF has no spherical or cylindrical joint: a tree
// with every joint type of the runtime (Spherical root; Rev, Prism, Planar, Cylindrical, Free, Fixed,
// a backward Spherical and a backward Rev), tilted gravity, velocity terms, damping and friction on
// a few dofs, <derivatives/>, one scene per integrator. The build tool make_programmatic_scenes
// emits its headers (rbdgen::emit::emitDynamicsHeader, as `rbdgen generate --scene` does) and
// test_scene_programmatic checks them against the runtime built from the same construction.

#include <string>

#include <rbd/scene/SceneLoader.h>

namespace sgprog
{

constexpr int kIntegrators = 3;
rbd::scene::Integrator integrator(int k);
/// Namespace of the header of integrator k: sgprog_semi, sgprog_explicit, sgprog_rk4.
std::string headerName(int k);

rbd::scene::SceneRobot sceneRobot();
rbd::scene::Scene scene(rbd::scene::Integrator integrator);

} // namespace sgprog
