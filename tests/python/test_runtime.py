"""rbdgen.Robot (the runtime) against independent truths: closed forms, finite differences,
identities between the functions, single calls vs batches vs threads."""
import math

import numpy as np
import pytest

import rbdgen
from conftest import ROBOTS, ROOT, SCENES, random_states, rel_err, unpack_mass_matrix

G = 9.81


@pytest.fixture(scope="module")
def ur5e():
    return rbdgen.Robot.from_urdf(ROBOTS / "ur5e.urdf")


@pytest.fixture(scope="module")
def quadruped():
    return rbdgen.Robot.from_urdf(ROBOTS / "quadruped.urdf", floating_base=True)


def test_sizes_and_names(ur5e, quadruped):
    assert (ur5e.nq, ur5e.nv) == (6, 6)
    assert len(ur5e.dof_names) == 6 and len(set(ur5e.dof_names)) == 6
    assert (quadruped.nq, quadruped.nv) == (19, 18)
    assert quadruped.dof_names[:6] == ["Root"] * 6
    assert len(quadruped.body_names) == quadruped.forward_kinematics(np.r_[1.0, np.zeros(18)]).shape[0]
    assert "ur5e" in repr(ur5e) or ur5e.name in repr(ur5e)


def test_pendulum_closed_form():
    """Point mass m = 1 at l = 1 below a y-axis hinge (+ 4e-5 kg m^2 about its centre)."""
    p = rbdgen.Robot.from_urdf(ROBOTS / "pendulum.urdf")
    inertia = 1.0 + 4e-5
    for theta, omega, tau in [(0.3, -1.2, 2.0), (-2.5, 0.7, -1.0), (math.pi / 2, 0.0, 0.0)]:
        q, v = np.array([theta]), np.array([omega])
        s, c = math.sin(theta), math.cos(theta)
        assert p.inverse_dynamics(q, v, np.array([0.5]))[0] == pytest.approx(inertia * 0.5 + G * s, rel=1e-13)
        assert p.mass_matrix(q)[0, 0] == pytest.approx(inertia, rel=1e-13)
        assert p.forward_dynamics(q, v, np.array([tau]))[0] == pytest.approx((tau - G * s) / inertia, rel=1e-12)
        np.testing.assert_allclose(p.center_of_mass(q), [-s, 0, -c], atol=1e-15)
        pose = p.forward_kinematics(q)[p.body_names.index("link1")]
        np.testing.assert_allclose(pose, [[c, 0, s, 0], [0, 1, 0, 0], [-s, 0, c, 0], [0, 0, 0, 1]], atol=1e-15)
        np.testing.assert_allclose(p.jacobian("link1", q), [[0], [1], [0], [0], [0], [0]], atol=1e-15)


def test_jacobian_is_the_derivative_of_forward_kinematics(ur5e):
    """Central differences of the link pose: linear rows = dp/dq, angular rows = axial(dR/dq R^T)."""
    q0, _, _ = random_states(ur5e, 5, seed=1)
    h = 1e-6
    for q in q0:
        for body, name in enumerate(ur5e.body_names):
            J = ur5e.jacobian(name, q)
            assert J.shape == (6, 6)
            for k in range(ur5e.nv):
                dq = np.zeros(ur5e.nq)
                dq[k] = h
                Tp, Tm = ur5e.forward_kinematics(q + dq)[body], ur5e.forward_kinematics(q - dq)[body]
                dp = (Tp[:3, 3] - Tm[:3, 3]) / (2 * h)
                W = (Tp[:3, :3] - Tm[:3, :3]) / (2 * h) @ ur5e.forward_kinematics(q)[body][:3, :3].T
                w = np.array([W[2, 1], W[0, 2], W[1, 0]])
                np.testing.assert_allclose(J[:3, k], w, atol=1e-8)
                np.testing.assert_allclose(J[3:, k], dp, atol=1e-8)
            np.testing.assert_array_equal(J, ur5e.jacobian(body, q))


def test_mass_matrix_columns_are_inverse_dynamics_differences(ur5e, quadruped):
    for robot, floating in [(ur5e, False), (quadruped, True)]:
        q, _, _ = random_states(robot, 3, seed=2, floating=floating)
        zero = np.zeros(robot.nv)
        for qi in q:
            H = robot.mass_matrix(qi)
            g = robot.inverse_dynamics(qi, zero, zero)
            cols = np.column_stack([robot.inverse_dynamics(qi, zero, e) - g for e in np.eye(robot.nv)])
            assert rel_err(H, cols) < 1e-12
            np.testing.assert_array_equal(H, H.T)
            assert np.linalg.eigvalsh(H).min() > 0


def test_mass_matrix_packed_is_mass_matrix_without_its_structural_zeros(ur5e, quadruped):
    """mass_matrix_entries comes from the kinematic tree (dofs i, j with one joint supporting the other)
    and mass_matrix(q) from CRBA: the entries left out are exactly 0 in H, the packed values are H's
    (one state and a batch); the quadruped's legs do not couple, the free base couples with all; a
    mimic gripper's coupled H (G^T H G) keeps the pattern of G^T pattern G."""
    mimic = rbdgen.Robot.from_urdf(ROOT / "tests" / "generator" / "mimic_gripper.urdf")
    for robot, floating in [(ur5e, False), (quadruped, True), (mimic, False)]:
        q, _, _ = random_states(robot, 4, seed=5, floating=floating)
        entries = robot.mass_matrix_entries
        H = robot.mass_matrix(q)
        np.testing.assert_array_equal(unpack_mass_matrix(robot, robot.mass_matrix_packed(q)), H)
        for i in range(len(q)):
            np.testing.assert_array_equal(robot.mass_matrix_packed(q[i]), H[i][entries[:, 0], entries[:, 1]])
        assert np.all(entries[:, 0] >= entries[:, 1])
        assert len({tuple(e) for e in entries}) == len(entries)
    n = ur5e.nv
    assert len(ur5e.mass_matrix_entries) == n * (n + 1) // 2  # a chain: every pair is on one path
    # the free base's 6 x 6 triangle, each of the 12 leg dofs with the 6 base dofs, each leg's 3 x 3 triangle
    assert len(quadruped.mass_matrix_entries) == 21 + 12 * 6 + 4 * 6


def test_forward_dynamics_inverts_inverse_dynamics(ur5e, quadruped):
    for robot, floating in [(ur5e, False), (quadruped, True)]:
        q, v, a = random_states(robot, 20, seed=3, floating=floating)
        tau = robot.inverse_dynamics(q, v, a)
        assert rel_err(robot.forward_dynamics(q, v, tau), a) < 1e-9


def test_gravity_torque_is_the_centre_of_mass_descent(ur5e):
    """tau_g = ID(q, 0, 0) = M g dz_com/dq (potential energy M g z_com), by central differences."""
    free = rbdgen.Robot.from_urdf(ROBOTS / "ur5e.urdf", floating_base=True)
    q = np.r_[1.0, np.zeros(6), random_states(ur5e, 1, seed=4)[0][0]]
    mass = free.mass_matrix(q)[3, 3]  # translational block of the free base = total mass
    qa = q[7:]
    zero = np.zeros(6)
    tau = ur5e.inverse_dynamics(qa, zero, zero)
    h = 1e-6
    dz = [(ur5e.center_of_mass(qa + h * e)[2] - ur5e.center_of_mass(qa - h * e)[2]) / (2 * h) for e in np.eye(6)]
    np.testing.assert_allclose(tau, mass * G * np.array(dz), atol=1e-6)


def test_batch_equals_loop_of_single_calls(quadruped):
    q, v, a = random_states(quadruped, 7, seed=5, floating=True)
    tau = quadruped.inverse_dynamics(q, v, a)
    assert tau.shape == (7, 18)
    checks = [
        (quadruped.forward_kinematics(q), lambda i: quadruped.forward_kinematics(q[i])),
        (tau, lambda i: quadruped.inverse_dynamics(q[i], v[i], a[i])),
        (quadruped.mass_matrix(q), lambda i: quadruped.mass_matrix(q[i])),
        (quadruped.forward_dynamics(q, v, tau), lambda i: quadruped.forward_dynamics(q[i], v[i], tau[i])),
        (quadruped.jacobian(quadruped.body_names[-1], q), lambda i: quadruped.jacobian(quadruped.body_names[-1], q[i])),
        (quadruped.center_of_mass(q), lambda i: quadruped.center_of_mass(q[i])),
    ]
    for batch, single in checks:
        assert batch.shape[0] == 7
        for i in range(7):
            np.testing.assert_array_equal(batch[i], single(i))


def test_threads_give_bitwise_the_same_results(quadruped):
    q, v, a = random_states(quadruped, 101, seed=6, floating=True)
    for threads in (2, 3, 200):
        np.testing.assert_array_equal(quadruped.inverse_dynamics(q, v, a), quadruped.inverse_dynamics(q, v, a, threads=threads))
        np.testing.assert_array_equal(quadruped.forward_dynamics(q, v, a), quadruped.forward_dynamics(q, v, a, threads=threads))
        np.testing.assert_array_equal(quadruped.mass_matrix(q), quadruped.mass_matrix(q, threads=threads))
        np.testing.assert_array_equal(quadruped.forward_kinematics(q), quadruped.forward_kinematics(q, threads=threads))
        np.testing.assert_array_equal(quadruped.jacobian(3, q), quadruped.jacobian(np.int64(3), q, threads=threads))
    # more threads than states, and than the cap of 256 threads per call
    np.testing.assert_array_equal(quadruped.mass_matrix(q[:3]), quadruped.mass_matrix(q[:3], threads=8))
    np.testing.assert_array_equal(quadruped.center_of_mass(q), quadruped.center_of_mass(q, threads=100000))


def test_empty_batch(ur5e):
    q = np.zeros((0, 6))
    assert ur5e.inverse_dynamics(q, q, q, threads=2).shape == (0, 6)
    assert ur5e.forward_kinematics(q).shape == (0, len(ur5e.body_names), 4, 4)


def test_base_link_changes_the_root_not_the_physics():
    """Rooted at its last link, the double pendulum's links keep their poses relative to each other
    (the dof order follows the new tree: dof_names says which joint each coordinate is)."""
    fixed = rbdgen.Robot.from_urdf(ROBOTS / "double_pendulum.urdf")
    rooted = rbdgen.Robot.from_urdf(ROBOTS / "double_pendulum.urdf", base_link="tip")
    assert rooted.nv == 2 and set(rooted.body_names) == set(fixed.body_names)
    assert rooted.dof_names == ["joint2", "joint1"]
    value = {"joint1": 0.4, "joint2": -1.1}
    pf = fixed.forward_kinematics(np.array([value[n] for n in fixed.dof_names]))
    pr = rooted.forward_kinematics(np.array([value[n] for n in rooted.dof_names]))
    i, j = fixed.body_names.index("base"), fixed.body_names.index("link2")
    k, m = rooted.body_names.index("base"), rooted.body_names.index("link2")
    np.testing.assert_allclose(np.linalg.inv(pf[i]) @ pf[j], np.linalg.inv(pr[k]) @ pr[m], atol=1e-14)


def test_scene_robot_has_the_scene_effects(scenes):
    """pendulum_damped: the scene's damping enters forward dynamics, the plain URDF has none."""
    scene = rbdgen.Robot.from_scene(scenes / "pendulum_damped.xml")
    assert scene.nv >= 1
    q, v, tau = np.full(scene.nq, 0.3), np.full(scene.nv, 1.5), np.zeros(scene.nv)
    a = scene.forward_dynamics(q, v, tau)
    np.testing.assert_allclose(scene.inverse_dynamics(q, v, a), tau, atol=1e-12)
    H = scene.mass_matrix(q)
    zero = np.zeros(scene.nv)
    # a one-dof pendulum has no velocity product: ID(q, v, 0) - ID(q, 0, 0) is the scene's damping 0.5 v
    np.testing.assert_allclose(scene.inverse_dynamics(q, v, zero) - scene.inverse_dynamics(q, zero, zero), 0.5 * v,
                               rtol=1e-13)
    plain = rbdgen.Robot.from_urdf(ROBOTS / "pendulum.urdf")
    np.testing.assert_allclose(plain.inverse_dynamics(q, v, zero), plain.inverse_dynamics(q, zero, zero), rtol=1e-14)
    np.testing.assert_allclose(H @ a, tau - scene.inverse_dynamics(q, v, zero), atol=1e-12)
    assert scene.center_of_mass(q).shape == (3,)
    assert scene.jacobian(scene.body_names[-1], q).shape == (6, scene.nv)


def test_batches_release_the_gil_and_share_the_robot(quadruped):
    """While a batch runs in one Python thread, others run Python code and call the same robot (single
    states and batches); every result equals the sequential one."""
    import threading

    q, v, a = random_states(quadruped, 10000, seed=9, floating=True)
    expected = quadruped.inverse_dynamics(q, v, a)
    results, progress = {}, []

    def batch(key):
        results[key] = quadruped.inverse_dynamics(q, v, a)

    workers = [threading.Thread(target=batch, args=(k,)) for k in range(3)]
    for w in workers:
        w.start()
    while any(w.is_alive() for w in workers):
        progress.append(quadruped.inverse_dynamics(q[7], v[7], a[7]))
    for w in workers:
        w.join()
    for k in range(3):
        np.testing.assert_array_equal(results[k], expected)
    assert len(progress) > 10  # the main thread ran while the batches did
    for tau in progress:
        np.testing.assert_array_equal(tau, expected[7])
