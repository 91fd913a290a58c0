"""rbdgen.compile: the generated code, compiled and imported, equals the runtime; the cache makes the
second call instant. One fixed-base robot with mimic joints (coupled: the runtime and the generated
module agree on the coupled coordinates), one floating-base robot and one scene (every effect:
damping, friction, armature, a contact, an external wrench held at zero; against
rbdgen.Robot.from_scene), each compile takes seconds."""
import os
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import rbdgen
from conftest import ROBOTS, ROOT, SCENES, assert_simd_close, random_states, rel_err, simd_growth, unpack_mass_matrix

BOUND = 1e-12  # max |generated - runtime| / max(1, max |runtime|), as tests/generator/test_generated


# tests/generator/mimic_gripper.urdf: 10 joints, 4 mimic joints coupled (a chain, siblings, across subtrees)
MIMIC_GRIPPER = ROOT / "tests" / "generator" / "mimic_gripper.urdf"
# tests/batch/double_pendulum_ground.xml: the double pendulum with every scene effect (a scene file)
SCENE = ROOT / "tests" / "batch" / "double_pendulum_ground.xml"
ROBOTS_COMPILED = [(MIMIC_GRIPPER, False), (ROBOTS / "quadruped.urdf", True), (SCENE, False)]


@pytest.fixture(scope="module")
def cache(tmp_path_factory):
    return tmp_path_factory.mktemp("rbdgen-cache")


@pytest.fixture(scope="module")
def heavy_pendulum(tmp_path_factory):
    """pendulum.urdf with a 2 kg bob: another URDF text."""
    heavy = tmp_path_factory.mktemp("urdf") / "heavy.urdf"
    heavy.write_bytes((ROBOTS / "pendulum.urdf").read_bytes().replace(b'<mass value="1"/>', b'<mass value="2"/>'))
    return heavy


@pytest.fixture(scope="module")
def first_compiles(cache, heavy_pendulum):
    """Every robot of this file compiled once, in parallel (compile releases the GIL while the C++
    compiler runs): {(urdf, floating): (robot, seconds)}."""
    def build(urdf, floating):
        start = time.perf_counter()
        if urdf == heavy_pendulum:  # (and without derivatives)
            robot = rbdgen.compile(urdf, floating_base=floating, derivatives=False, cache=cache)
        elif urdf == SCENE:
            robot = rbdgen.compile(urdf, cache=cache)
        else:
            robot = rbdgen.compile(urdf, floating_base=floating, cache=cache)
        return robot, time.perf_counter() - start

    jobs = ROBOTS_COMPILED + [(heavy_pendulum, False)]
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        futures = {job: pool.submit(build, *job) for job in jobs}
        return {job: f.result() for job, f in futures.items()}


@pytest.fixture(scope="module", params=ROBOTS_COMPILED, ids=["mimic_gripper", "quadruped_floating", "scene"])
def pair(request, first_compiles):
    urdf, floating = request.param
    compiled, first = first_compiles[(urdf, floating)]
    runtime = rbdgen.Robot.from_scene(urdf) if urdf == SCENE else rbdgen.Robot.from_urdf(urdf, floating_base=floating)
    return compiled, runtime, floating, first


def test_same_robot(pair):
    compiled, runtime, floating, _ = pair
    assert (compiled.nq, compiled.nv) == (runtime.nq, runtime.nv)
    assert compiled.dof_names == runtime.dof_names
    assert compiled.body_names == runtime.body_names
    assert compiled.name == runtime.name
    assert compiled.has_forward_dynamics
    assert compiled.has_derivatives
    if compiled.name == "mimic_gripper":  # 10 joints, finger_r, knuckle, camera and flap follow others
        assert compiled.nv == 6 and "finger_r_joint" not in compiled.dof_names


def test_generated_equals_runtime(pair):
    compiled, runtime, floating, _ = pair
    q, v, a = random_states(runtime, 50, seed=7, floating=floating)
    assert rel_err(compiled.forward_kinematics(q), runtime.forward_kinematics(q)) < BOUND
    assert rel_err(compiled.inverse_dynamics(q, v, a), runtime.inverse_dynamics(q, v, a)) < BOUND
    assert rel_err(compiled.mass_matrix(q), runtime.mass_matrix(q)) < BOUND
    # the packed mass matrix: its entries put back give H (the others are structural zeros)
    entries = compiled.mass_matrix_entries
    assert entries.shape[1] == 2 and np.all(entries[:, 0] >= entries[:, 1])
    assert rel_err(unpack_mass_matrix(compiled, compiled.mass_matrix_packed(q)), runtime.mass_matrix(q)) < BOUND
    assert rel_err(compiled.center_of_mass(q), runtime.center_of_mass(q)) < BOUND
    for body in runtime.body_names:
        assert rel_err(compiled.jacobian(body, q), runtime.jacobian(body, q)) < BOUND, body
    # forward dynamics: two correct solvers differ by about cond(H) eps (here cond(H) < 1e5)
    assert rel_err(compiled.forward_dynamics(q, v, a), runtime.forward_dynamics(q, v, a)) < 1e-10


def test_generated_derivatives_equal_runtime(pair):
    """Against the runtime's derivatives (themselves checked against finite differences in
    test_derivatives.py); d a/dq carries H^-1 twice: a looser bound, as in tests/generator."""
    compiled, runtime, floating, _ = pair
    q, v, a = random_states(runtime, 20, seed=10, floating=floating)
    for x, y in zip(compiled.inverse_dynamics_derivatives(q, v, a), runtime.inverse_dynamics_derivatives(q, v, a)):
        assert rel_err(x, y) < BOUND
    names = ["a", "da_dq", "da_dv", "Minv"]
    for name, x, y, bound in zip(names, compiled.forward_dynamics_derivatives(q, v, a),
                                 runtime.forward_dynamics_derivatives(q, v, a), [1e-12, 1e-10, 1e-10, 1e-12]):
        assert rel_err(x, y) < bound, name
    # batch (SIMD packs) = single calls, any thread count
    fds = compiled.forward_dynamics_derivatives(q, v, a, threads=3)
    ids = compiled.inverse_dynamics_derivatives(q, v, a, threads=2)
    for x, y in zip(fds, compiled.forward_dynamics_derivatives(q, v, a)):
        np.testing.assert_array_equal(x, y)
    for x, y in zip(ids, compiled.inverse_dynamics_derivatives(q, v, a, threads=5)):
        np.testing.assert_array_equal(x, y)
    for i in (0, 7, 19):
        grow = simd_growth(compiled, q[i])
        for x, y, g in zip(fds, compiled.forward_dynamics_derivatives(q[i], v[i], a[i]), [grow, grow * grow, grow, grow]):
            assert_simd_close(x[i], y, g)
        for x, y in zip(ids, compiled.inverse_dynamics_derivatives(q[i], v[i], a[i])):
            assert_simd_close(x[i], y)


def test_compiled_batch_threads_and_errors(pair):
    compiled, runtime, floating, _ = pair
    q, v, a = random_states(runtime, 33, seed=8, floating=floating)
    tau = compiled.inverse_dynamics(q, v, a, threads=2)
    np.testing.assert_array_equal(tau, compiled.inverse_dynamics(q, v, a))
    for i in range(len(q)):
        assert_simd_close(tau[i], compiled.inverse_dynamics(q[i], v[i], a[i]))
    np.testing.assert_array_equal(compiled.forward_dynamics(q, v, tau, threads=3), compiled.forward_dynamics(q, v, tau))
    assert rel_err(compiled.forward_dynamics(q, v, tau), a) < 1e-9
    with pytest.raises(ValueError, match=r"argument 'q' must have shape \(%d,\) or \(N, %d\)" % (runtime.nq, runtime.nq)):
        compiled.mass_matrix(np.zeros(runtime.nq + 1))
    with pytest.raises(TypeError, match="dtype float64"):
        compiled.mass_matrix(np.zeros(runtime.nq, dtype=np.float32))
    with pytest.raises(KeyError, match="unknown link"):
        compiled.jacobian("nope", q[0])


@pytest.mark.parametrize("n", [1, 3, 33, 130])
def test_compiled_batches_run_on_simd_packs(pair, n):
    """Every function of a batch (NS/batch.hpp: packs of 2 to 16 states, a partial last pack, blocks of
    64 states per call) against single calls, and bitwise the same for every thread count."""
    compiled, runtime, floating, _ = pair
    q, v, a = random_states(runtime, n, seed=20 + n, floating=floating)
    body = runtime.body_names[-1]
    functions = [
        (lambda th: compiled.forward_kinematics(q, threads=th), lambda i: compiled.forward_kinematics(q[i]), False),
        (lambda th: compiled.inverse_dynamics(q, v, a, threads=th), lambda i: compiled.inverse_dynamics(q[i], v[i], a[i]), False),
        (lambda th: compiled.mass_matrix(q, threads=th), lambda i: compiled.mass_matrix(q[i]), False),
        (lambda th: compiled.mass_matrix_packed(q, threads=th), lambda i: compiled.mass_matrix_packed(q[i]), False),
        (lambda th: compiled.forward_dynamics(q, v, a, threads=th), lambda i: compiled.forward_dynamics(q[i], v[i], a[i]), True),
        (lambda th: compiled.jacobian(body, q, threads=th), lambda i: compiled.jacobian(body, q[i]), False),
        (lambda th: compiled.center_of_mass(q, threads=th), lambda i: compiled.center_of_mass(q[i]), False),
    ]
    for batch, single, dynamics in functions:
        out = batch(1)
        assert out.shape[0] == n
        for threads in (2, 3, 7):
            np.testing.assert_array_equal(out, batch(threads))
        for i in range(n):
            assert_simd_close(out[i], single(i), simd_growth(compiled, q[i]) if dynamics else 1.0)


def test_second_call_is_instant(pair, cache):
    compiled, runtime, floating, first = pair
    path = {"mimic_gripper": MIMIC_GRIPPER, "quadruped": ROBOTS / "quadruped.urdf", "double_pendulum_ground": SCENE}[compiled.name]
    start = time.perf_counter()
    again = rbdgen.compile(path, floating_base=floating, cache=cache)
    second = time.perf_counter() - start
    assert second < 0.1 and second < first / 20, (first, second)
    q = np.zeros(runtime.nq)
    q[0] = 1.0
    np.testing.assert_array_equal(again.mass_matrix(q), compiled.mass_matrix(q))


def test_cache_is_keyed_by_the_inputs(cache, heavy_pendulum, first_compiles):
    """Another URDF text (a heavier bob) gives another module, equal to the runtime on that text; the
    key changes with every input (checked on the key itself: each compile takes seconds)."""
    from rbdgen import _compile
    urdf = (ROBOTS / "pendulum.urdf").read_bytes()
    heavy = heavy_pendulum
    compiled = first_compiles[(heavy, False)][0]
    modules = {d.name for d in cache.iterdir() if d.name.startswith("rbdgen_robot_") and ".tmp-" not in d.name}
    assert len(modules) == 4  # one per robot of first_compiles, nothing left over from the builds
    assert len({d.name for d in cache.iterdir()}) == 4
    q = np.array([0.5])
    assert compiled.mass_matrix(q)[0, 0] == pytest.approx(2 + 4e-5, rel=1e-14)
    assert rel_err(compiled.inverse_dynamics(q, q, q), rbdgen.Robot.from_urdf(heavy).inverse_dynamics(q, q, q)) < BOUND
    assert not compiled.has_derivatives  # compiled with derivatives=False
    with pytest.raises(RuntimeError, match="inverse_dynamics_derivatives: not available .*without derivatives"):
        compiled.inverse_dynamics_derivatives(q, q, q)
    with pytest.raises(RuntimeError, match="forward_dynamics_derivatives: not available"):
        compiled.forward_dynamics_derivatives(q, q, q)
    key = _compile._key(urdf, False, None, "c++")
    assert key == _compile._key(urdf, False, None, "c++")
    others = [_compile._key(urdf.replace(b"1", b"2", 1), False, None, "c++"), _compile._key(urdf, True, None, "c++"),
              _compile._key(urdf, False, "link1", "c++"), _compile._key(urdf, False, None, "clang++"),
              _compile._key(urdf, False, None, "c++", derivatives=False),
              # a scene's key holds its URDF's bytes (the scene names it)
              _compile._key(urdf, False, None, "c++", scene_urdf=ROBOTS / "pendulum.urdf"),
              _compile._key(urdf, False, None, "c++", scene_urdf=heavy)]
    assert len({key, *others}) == 8


def test_compile_errors(tmp_path, cache):
    with pytest.raises(FileNotFoundError):
        rbdgen.compile(tmp_path / "missing.urdf", cache=cache)
    with pytest.raises(ValueError, match="scene file: its base comes from the scene"):
        rbdgen.compile(SCENES / "pendulum_damped.xml", floating_base=True, cache=cache)
    broken_scene = tmp_path / "broken_scene.xml"
    broken_scene.write_text('<scene name="s"><robot urdf="missing.urdf" base="fixed"/></scene>')
    with pytest.raises(ValueError, match="missing.urdf"):
        rbdgen.compile(broken_scene, cache=cache)
    broken = tmp_path / "broken.urdf"
    broken.write_text('<robot name="r"><link name="a" mass="x"/><joint name="j" type="revolute"/></robot>')
    with pytest.raises(ValueError, match="broken.urdf"):
        rbdgen.compile(broken, cache=cache)
    with pytest.raises(RuntimeError, match="compiler failed"):
        rbdgen.compile(ROBOTS / "pendulum.urdf", cache=cache, cxx="false")


def test_compiled_scene_has_its_effects(first_compiles):
    """The compiled scene at rest with its tip 0.22 m into the ground: the URDF's gravity torques minus
    J_tip^T f of the compliant contact (f = k depth upwards, no friction at rest), computed here."""
    compiled = first_compiles[(SCENE, False)][0]
    plain = rbdgen.Robot.from_urdf(ROBOTS / "double_pendulum.urdf")
    q = np.array([0.3, 0.0])
    zero = np.zeros(2)
    depth = -1.5 + 1.8 * np.cos(0.3)  # ground at z = -1.5, the tip 1.8 m below the pivot along the links
    f = np.array([0.0, 0.0, 5000.0 * depth])
    expected = plain.inverse_dynamics(q, zero, zero) - plain.jacobian("tip", q)[3:].T @ f
    assert depth > 0.2
    assert rel_err(compiled.inverse_dynamics(q, zero, zero), expected) < 1e-12
    # out of the ground: the URDF's gravity torques only
    q_free = np.array([1.2, 0.0])
    assert rel_err(compiled.inverse_dynamics(q_free, zero, zero), plain.inverse_dynamics(q_free, zero, zero)) < 1e-12
