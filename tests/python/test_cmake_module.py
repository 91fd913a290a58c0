"""generate_robot_dynamics(... PYTHON_MODULE name) in a downstream CMake build against an installed
rbdgen, of a URDF and of a scene: the modules import and equal the runtime (Robot.from_urdf,
Robot.from_scene), derivatives included (run by ctest's python_tests,
which says where the build is). The prefix gets rbdgen (libraries, the rbdgen executable, the CMake
package) from $RBDGEN_TEST_GENERATOR_BUILD when set (scripts/test.sh: its sanitized build, which
has built the executable anyway; the module links none of its libraries), else from this build,
and this build's Python package (component python), as a distribution would package them."""
import importlib.util
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import rbdgen
from conftest import ROBOTS, random_states, rel_err

BUILD = os.environ.get("RBDGEN_TEST_BUILD_DIR")
GENERATOR_BUILD = os.environ.get("RBDGEN_TEST_GENERATOR_BUILD") or BUILD
HERE = Path(__file__).resolve().parent


def run(cmd):
    result = subprocess.run([str(c) for c in cmd], capture_output=True, text=True)
    assert result.returncode == 0, "%s\n%s\n%s" % (" ".join(map(str, cmd)), result.stdout[-3000:], result.stderr[-3000:])
    return result.stdout


@pytest.mark.skipif(not BUILD, reason="needs the build directory (set by ctest)")
@pytest.mark.skipif(bool(BUILD) and not (Path(GENERATOR_BUILD) / "generator" / "rbdgen").exists(),
                    reason="no rbdgen executable in %s (cmake --build BUILD --target rbdgen)" % GENERATOR_BUILD)
def test_python_module_of_a_downstream_build(tmp_path):
    prefix, build = tmp_path / "prefix", tmp_path / "build"
    run(["cmake", "--install", GENERATOR_BUILD, "--prefix", prefix])
    run(["cmake", "--install", BUILD, "--component", "python", "--prefix", prefix])
    urdf = ROBOTS / "double_pendulum.urdf"
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    # no build type: no optimisation, the quickest compile (-O2 and LTO would add ~10 s)
    scene = HERE.parent / "batch" / "double_pendulum_ground.xml"  # the same robot with every scene effect
    run(["cmake", "-S", HERE / "cmake_module", "-B", build, *generator, "-DCMAKE_BUILD_TYPE=",
         "-DCMAKE_PREFIX_PATH=%s" % prefix, "-DPython3_EXECUTABLE=%s" % sys.executable, "-DURDF=%s" % urdf,
         "-DSCENE=%s" % scene])
    run(["cmake", "--build", build])

    def load(name):
        spec = importlib.util.spec_from_file_location(name, next(build.glob(name + "*.so")))
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        return module.robot()

    # the scene's module (SCENE ... PYTHON_MODULE) = rbdgen.Robot.from_scene, derivatives included
    scene_robot, scene_runtime = load("my_scene_py"), rbdgen.Robot.from_scene(scene)
    assert (scene_robot.name, scene_robot.nv, scene_robot.has_derivatives) == ("double_pendulum_ground", 2, True)
    q, v, a = random_states(scene_runtime, 10, seed=15, floating=False)
    assert rel_err(scene_robot.inverse_dynamics(q, v, a), scene_runtime.inverse_dynamics(q, v, a)) < 1e-12
    assert rel_err(scene_robot.forward_dynamics(q, v, a), scene_runtime.forward_dynamics(q, v, a)) < 1e-10
    for x, y in zip(scene_robot.inverse_dynamics_derivatives(q, v, a), scene_runtime.inverse_dynamics_derivatives(q, v, a)):
        assert rel_err(x, y) < 1e-12

    robot = load("my_robot_py")
    runtime = rbdgen.Robot.from_urdf(urdf, floating_base=False)
    assert (robot.nq, robot.nv, robot.name) == (runtime.nq, runtime.nv, runtime.name)
    assert robot.dof_names == runtime.dof_names and robot.body_names == runtime.body_names
    assert robot.has_forward_dynamics and robot.has_derivatives
    q, v, a = random_states(runtime, 10, seed=14, floating=False)
    assert rel_err(robot.inverse_dynamics(q, v, a), runtime.inverse_dynamics(q, v, a)) < 1e-12
    assert rel_err(robot.mass_matrix(q), runtime.mass_matrix(q)) < 1e-12
    assert rel_err(robot.forward_dynamics(q, v, a), runtime.forward_dynamics(q, v, a)) < 1e-10
    for x, y in zip(robot.inverse_dynamics_derivatives(q, v, a, threads=2), runtime.inverse_dynamics_derivatives(q, v, a)):
        assert rel_err(x, y) < 1e-12
    for x, y, bound in zip(robot.forward_dynamics_derivatives(q, v, a), runtime.forward_dynamics_derivatives(q, v, a),
                           [1e-12, 1e-10, 1e-10, 1e-12]):
        assert rel_err(x, y) < bound
    with pytest.raises(ValueError, match=r"argument 'q' must have shape \(2,\) or \(N, 2\)"):
        robot.inverse_dynamics_derivatives(np.zeros(3), v[0], a[0])
    # a second build does nothing
    assert "no work to do" in run(["cmake", "--build", build]) or not generator
