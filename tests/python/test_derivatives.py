"""The derivatives of rbdgen.Robot (the runtime) against finite differences of the same object's
inverse_dynamics and forward_dynamics, and batches against single calls.

d/dq is taken in the tangent space: q ⊕ ε e_m moves dof m by its motion subspace. For revolute
joints that is q_m + ε; for the free base of a floating robot (q = [qw qx qy qz x y z ...], v =
[w; v] in the base frame) it is quat ⊗ exp(ε e_m / 2) for m < 3 and x += ε R(quat) e_(m-3) for
3 <= m < 6 (rbd/EulerIntegration.h), which `step` below writes out (the package has no integrator).
The generated code's derivatives are compared with these in test_compile.py."""
from pathlib import Path

import numpy as np
import pytest

import rbdgen
from conftest import ROBOTS, SCENES, random_states, rel_err

H = 1e-3  # 4th-order central differences: truncation ~H^4, rounding ~1e-16 / H
FD_BOUND = 1e-8  # max |analytic - differences| / max(1, max |differences|) (seen: 1e-12 for d/dq, 1.3e-9 for d a/dv: rounding)


def quat_mul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return np.array([aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw])


def quat_rot(quat):
    w, x, y, z = quat / np.linalg.norm(quat)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def step(q, m, eps, floating):
    """q ⊕ eps e_m (revolute joints, and a free base first when floating)."""
    q = q.copy()
    if not floating:
        q[m] += eps
    elif m < 3:
        half = np.zeros(4)
        half[0], half[1 + m] = np.cos(eps / 2), np.sin(eps / 2)
        q[:4] = quat_mul(q[:4], half)
    elif m < 6:
        q[4:7] += eps * quat_rot(q[:4])[:, m - 3]
    else:
        q[m + 1] += eps
    return q


def differences(f, x0, nv, move, h=H):
    """Columns d f(move(x0, m, eps)) / d eps at 0 for m < nv, by 4th-order central differences; f is
    evaluated once on the batch of every perturbed x."""
    offsets = (2 * h, h, -h, -2 * h)
    weights = np.array([-1, 8, -8, 1]) / (12 * h)
    xs = np.array([move(x0, m, e) for m in range(nv) for e in offsets])
    fx = f(xs).reshape(nv, len(offsets), -1)
    return np.einsum("k,mki->im", weights, fx)


def add(x, m, eps):
    x = x.copy()
    x[m] += eps
    return x


@pytest.fixture(scope="module", params=[("ur5e.urdf", False), ("quadruped.urdf", True)], ids=["ur5e", "quadruped_floating"])
def case(request):
    urdf, floating = request.param
    return rbdgen.Robot.from_urdf(ROBOTS / urdf, floating_base=floating), floating


def test_inverse_dynamics_derivatives_are_differences(case):
    robot, floating = case
    n = robot.nv
    q, v, a = random_states(robot, 3, seed=11, floating=floating)
    for qi, vi, ai in zip(q, v, a):
        dtau_dq, dtau_dv = robot.inverse_dynamics_derivatives(qi, vi, ai)
        assert dtau_dq.shape == dtau_dv.shape == (n, n)
        ones = lambda x: np.repeat(x[None], 4 * n, axis=0)  # noqa: E731
        num_dq = differences(lambda qs: robot.inverse_dynamics(qs, ones(vi), ones(ai)), qi, n,
                             lambda x, m, e: step(x, m, e, floating))
        num_dv = differences(lambda vs: robot.inverse_dynamics(ones(qi), vs, ones(ai)), vi, n, add)
        assert rel_err(dtau_dq, num_dq) < FD_BOUND
        assert rel_err(dtau_dv, num_dv) < FD_BOUND


def test_forward_dynamics_derivatives_are_differences(case):
    robot, floating = case
    n = robot.nv
    q, v, tau = random_states(robot, 3, seed=12, floating=floating)
    tau *= 10
    for qi, vi, ti in zip(q, v, tau):
        a, da_dq, da_dv, Minv = robot.forward_dynamics_derivatives(qi, vi, ti)
        assert a.shape == (n,) and da_dq.shape == da_dv.shape == Minv.shape == (n, n)
        assert rel_err(a, robot.forward_dynamics(qi, vi, ti)) < 1e-12
        ones = lambda x: np.repeat(x[None], 4 * n, axis=0)  # noqa: E731
        num_dq = differences(lambda qs: robot.forward_dynamics(qs, ones(vi), ones(ti)), qi, n,
                             lambda x, m, e: step(x, m, e, floating))
        num_dv = differences(lambda vs: robot.forward_dynamics(ones(qi), vs, ones(ti)), vi, n, add)
        num_dtau = differences(lambda ts: robot.forward_dynamics(ones(qi), ones(vi), ts), ti, n, add)
        assert rel_err(da_dq, num_dq) < FD_BOUND
        assert rel_err(da_dv, num_dv) < FD_BOUND
        assert rel_err(Minv, num_dtau) < FD_BOUND
        assert rel_err(Minv @ robot.mass_matrix(qi), np.eye(n)) < 1e-12
        # the chain rule through inverse dynamics: da = -Minv dID at a
        dtau_dq, dtau_dv = robot.inverse_dynamics_derivatives(qi, vi, a)
        assert rel_err(da_dq, -Minv @ dtau_dq) < 1e-12
        assert rel_err(da_dv, -Minv @ dtau_dv) < 1e-12


def test_batches_equal_single_calls_for_any_thread_count(case):
    robot, floating = case
    q, v, a = random_states(robot, 9, seed=13, floating=floating)
    ids = robot.inverse_dynamics_derivatives(q, v, a)
    fds = robot.forward_dynamics_derivatives(q, v, a)
    assert [x.shape for x in ids] == [(9, robot.nv, robot.nv)] * 2
    assert [x.shape for x in fds] == [(9, robot.nv)] + [(9, robot.nv, robot.nv)] * 3
    for i in range(9):
        for batch, single in zip(ids, robot.inverse_dynamics_derivatives(q[i], v[i], a[i])):
            np.testing.assert_array_equal(batch[i], single)
        for batch, single in zip(fds, robot.forward_dynamics_derivatives(q[i], v[i], a[i])):
            np.testing.assert_array_equal(batch[i], single)
    for threads in (2, 5):
        for x, y in zip(ids, robot.inverse_dynamics_derivatives(q, v, a, threads=threads)):
            np.testing.assert_array_equal(x, y)
        for x, y in zip(fds, robot.forward_dynamics_derivatives(q, v, a, threads=threads)):
            np.testing.assert_array_equal(x, y)
    empty = np.zeros((0, robot.nv))
    assert robot.forward_dynamics_derivatives(np.zeros((0, robot.nq)), empty, empty)[1].shape == (0, robot.nv, robot.nv)


def test_scene_derivatives_include_its_damping():
    """pendulum_damped: dtau/dv = the scene's damping 0.5 (one dof: no velocity product), and FD's
    derivatives are differences of the scene's forward dynamics."""
    scene = rbdgen.Robot.from_scene(SCENES / "pendulum_damped.xml")
    assert scene.has_derivatives
    q, v, tau = np.array([0.7]), np.array([-1.3]), np.array([0.4])
    dtau_dq, dtau_dv = scene.inverse_dynamics_derivatives(q, v, tau)
    np.testing.assert_allclose(dtau_dv, [[0.5]], rtol=1e-14)
    a, da_dq, da_dv, Minv = scene.forward_dynamics_derivatives(q, v, tau)
    np.testing.assert_allclose(da_dv, -Minv @ dtau_dv, rtol=1e-14)
    num_dq = differences(lambda qs: scene.forward_dynamics(qs, np.repeat(v[None], 4, 0), np.repeat(tau[None], 4, 0)),
                         q, 1, add)
    assert rel_err(da_dq, num_dq) < FD_BOUND
    assert rel_err(Minv, np.linalg.inv(scene.mass_matrix(q))) < 1e-14


def test_scene_derivatives_with_contacts_are_differences():
    """quadruped_standing lowered 17 mm: its four feet 6.5 mm into the compliant ground (no contact
    boundary within the differences' steps), slipping (regularised Coulomb friction), with joint
    damping, friction and armature; derivatives against differences of the scene's forward dynamics."""
    scene = rbdgen.Robot.from_scene(SCENES / "quadruped_standing.xml")
    assert scene.has_derivatives and (scene.nq, scene.nv) == (19, 18)
    q = np.r_[1.0, 0, 0, 0, 0, 0, 0.275, [0, -0.8, 1.6] * 4]
    rng = np.random.default_rng(15)
    v, tau = rng.uniform(-0.5, 0.5, scene.nv), rng.uniform(-5, 5, scene.nv)
    a, da_dq, da_dv, Minv = scene.forward_dynamics_derivatives(q, v, tau)
    assert rel_err(a, scene.forward_dynamics(q, v, tau)) < 1e-12
    n = scene.nv
    ones = lambda x: np.repeat(x[None], 4 * n, axis=0)  # noqa: E731
    h = 1e-5  # (the friction's regularisation velocity is 0.05 m/s: smaller steps than the arm's)
    num_dq = differences(lambda qs: scene.forward_dynamics(qs, ones(v), ones(tau)), q, n,
                         lambda x, m, e: step(x, m, e, True), h)
    num_dv = differences(lambda vs: scene.forward_dynamics(ones(q), vs, ones(tau)), v, n, add, h)
    assert np.abs(da_dq).max() > 1e3  # the ground's stiffness is in there
    assert rel_err(da_dq, num_dq) < 1e-9  # seen 5e-12
    assert rel_err(da_dv, num_dv) < 1e-9  # seen 3e-11
    dtau_dq, dtau_dv = scene.inverse_dynamics_derivatives(q, v, a)
    assert rel_err(da_dq, -Minv @ dtau_dq) < 1e-12


def test_scene_with_mimic_joints_is_the_coupled_urdf_model(tmp_path):
    """Robot.from_scene couples mimic joints as Robot.from_urdf does: a scene of the gripper (mimic
    pair, chain, across subtrees) with gravity and velocity terms only is the same system, evaluated
    through the scene's code (rbd::scene::SceneDynamics, projected) and the URDF model's (rbd::)."""
    gripper = Path(__file__).resolve().parents[1] / "generator" / "mimic_gripper.urdf"
    xml = tmp_path / "gripper.xml"
    xml.write_text('<scene name="gripper"><robot urdf="%s" base="floating"/><gravity/></scene>' % gripper)
    scene = rbdgen.Robot.from_scene(xml)
    urdf = rbdgen.Robot.from_urdf(gripper, floating_base=True)
    assert (scene.nq, scene.nv) == (urdf.nq, urdf.nv) == (13, 12)  # 17 / 16 with the 4 mimic joints
    assert scene.dof_names == urdf.dof_names
    q, v, a = random_states(urdf, 4, seed=41, floating=True)
    for qi, vi, ai in zip(q, v, a):
        assert rel_err(scene.inverse_dynamics(qi, vi, ai), urdf.inverse_dynamics(qi, vi, ai)) < 1e-12
        assert rel_err(scene.mass_matrix(qi), urdf.mass_matrix(qi)) < 1e-12
        assert rel_err(scene.forward_dynamics(qi, vi, ai), urdf.forward_dynamics(qi, vi, ai)) < 1e-10
        assert rel_err(scene.forward_kinematics(qi), urdf.forward_kinematics(qi)) < 1e-13
        assert rel_err(scene.jacobian("flap", qi), urdf.jacobian("flap", qi)) < 1e-13
        assert rel_err(scene.center_of_mass(qi), urdf.center_of_mass(qi)) < 1e-13
        for x, y in zip(scene.inverse_dynamics_derivatives(qi, vi, ai), urdf.inverse_dynamics_derivatives(qi, vi, ai)):
            assert rel_err(x, y) < 1e-11
        for x, y in zip(scene.forward_dynamics_derivatives(qi, vi, ai), urdf.forward_dynamics_derivatives(qi, vi, ai)):
            assert rel_err(x, y) < 1e-9
