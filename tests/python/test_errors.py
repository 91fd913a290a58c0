"""Bad input raises a Python exception naming the argument and the expected shape; never a crash,
never a silent copy into another layout."""
import numpy as np
import pytest

import rbdgen
from conftest import ROBOTS, SCENES


@pytest.fixture(scope="module")
def ur5e():
    return rbdgen.Robot.from_urdf(ROBOTS / "ur5e.urdf")


Q = np.zeros(6)


@pytest.mark.parametrize("bad, message", [
    (np.zeros(5), r"argument 'q' must have shape \(6,\) or \(N, 6\), got \(5,\)"),
    (np.zeros((3, 7)), r"argument 'q' must have shape \(6,\) or \(N, 6\), got \(3, 7\)"),
    (np.zeros((2, 3, 6)), r"argument 'q' must have shape \(6,\) or \(N, 6\), got \(2, 3, 6\)"),
    (np.array(1.0), r"argument 'q' must have shape \(6,\) or \(N, 6\), got \(\)"),
    (np.zeros((4, 12))[:, ::2], r"argument 'q' must be C-contiguous"),
    (np.zeros((6, 4)).T, r"argument 'q' must be C-contiguous"),
    (np.array([0, 0, np.nan, 0, 0, 0]), r"argument 'q' has a non-finite value at \[2\]"),
    (np.array([[0.0] * 6, [0, 0, 0, 0, np.inf, 0]]), r"argument 'q' has a non-finite value at \[1, 4\]"),
])
def test_bad_q_raises_value_error(ur5e, bad, message):
    with pytest.raises(ValueError, match=message):
        ur5e.mass_matrix(bad)
    other = np.zeros(bad.shape[:-1] + (6,)) if bad.ndim in (1, 2) else Q  # v, a: the batch of bad
    with pytest.raises(ValueError, match=message):
        ur5e.inverse_dynamics(bad, other, other)
    with pytest.raises(ValueError, match=message.replace("'q'", "'a'")):
        ur5e.inverse_dynamics(other, other, bad)


@pytest.mark.parametrize("dtype", [np.float32, np.int64, np.complex128, ">f8"])
def test_other_dtypes_raise_type_error(ur5e, dtype):
    with pytest.raises(TypeError, match=r"forward_kinematics: argument 'q' must have dtype float64"):
        ur5e.forward_kinematics(np.zeros(6, dtype=dtype))


def test_non_arrays_raise_type_error(ur5e):
    with pytest.raises(TypeError, match=r"argument 'q' must be a float64 numpy array of shape \(6,\) or \(N, 6\)"):
        ur5e.center_of_mass("000000")
    with pytest.raises(TypeError):
        ur5e.center_of_mass(None)


def test_lists_are_converted(ur5e):
    np.testing.assert_array_equal(ur5e.center_of_mass([0.0] * 6), ur5e.center_of_mass(Q))
    with pytest.raises(ValueError, match="argument 'q' must have shape"):
        ur5e.center_of_mass([0.0] * 5)


def test_mismatched_batches(ur5e):
    with pytest.raises(ValueError, match=r"inverse_dynamics: argument 'v' must have shape \(3, 6\) like 'q', got \(6,\)"):
        ur5e.inverse_dynamics(np.zeros((3, 6)), Q, np.zeros((3, 6)))
    with pytest.raises(ValueError, match=r"forward_dynamics: argument 'tau' must have shape \(3, 6\) like 'q', got \(2, 6\)"):
        ur5e.forward_dynamics(np.zeros((3, 6)), np.zeros((3, 6)), np.zeros((2, 6)))
    with pytest.raises(ValueError, match=r"argument 'a' must have shape \(6,\) like 'q', got \(1, 6\)"):
        ur5e.inverse_dynamics(Q, Q, np.zeros((1, 6)))
    with pytest.raises(ValueError, match=r"argument 'v' must have shape \(6,\) or \(N, 6\), got \(7,\)"):
        ur5e.inverse_dynamics(Q, np.zeros(7), Q)


@pytest.mark.parametrize("fn, third", [("inverse_dynamics_derivatives", "a"), ("forward_dynamics_derivatives", "tau")])
def test_derivatives_check_their_arguments(ur5e, fn, third):
    f = getattr(ur5e, fn)
    with pytest.raises(ValueError, match=r"%s: argument 'q' must have shape \(6,\) or \(N, 6\), got \(7,\)" % fn):
        f(np.zeros(7), Q, Q)
    with pytest.raises(ValueError, match=r"%s: argument 'v' must have shape \(4, 6\) like 'q', got \(6,\)" % fn):
        f(np.zeros((4, 6)), Q, np.zeros((4, 6)))
    with pytest.raises(ValueError, match=r"%s: argument '%s' must have shape \(6,\) or \(N, 6\), got \(2, 5\)" % (fn, third)):
        f(np.zeros((2, 6)), np.zeros((2, 6)), np.zeros((2, 5)))
    with pytest.raises(ValueError, match=r"%s: argument '%s' has a non-finite value at \[1\]" % (fn, third)):
        f(Q, Q, np.array([0, np.nan, 0, 0, 0, 0]))
    with pytest.raises(TypeError, match=r"%s: argument 'v' must have dtype float64" % fn):
        f(Q, np.zeros(6, dtype=np.float32), Q)
    with pytest.raises(ValueError, match=r"%s: argument 'q' must be C-contiguous" % fn):
        f(np.zeros((2, 12))[:, ::2], np.zeros((2, 6)), np.zeros((2, 6)))


def test_unknown_links(ur5e):
    with pytest.raises(KeyError, match="jacobian: argument 'body': unknown link 'hand'"):
        ur5e.jacobian("hand", Q)
    with pytest.raises(IndexError, match="index 99 out of range"):
        ur5e.jacobian(99, Q)
    with pytest.raises(IndexError):
        ur5e.jacobian(-1, Q)
    with pytest.raises(TypeError, match="argument 'body' must be a link name"):
        ur5e.jacobian(1.5, Q)


def test_bad_threads(ur5e):
    with pytest.raises(ValueError, match="threads must be >= 1"):
        ur5e.mass_matrix(np.zeros((2, 6)), threads=0)
    with pytest.raises(TypeError):
        ur5e.mass_matrix(Q, 2)  # threads is keyword-only


def test_bad_files(tmp_path):
    with pytest.raises(FileNotFoundError, match="nothing.urdf"):
        rbdgen.Robot.from_urdf(tmp_path / "nothing.urdf")
    broken = tmp_path / "broken.urdf"
    broken.write_text('<robot name="r"><link name="a"/><joint name="j" type="revolute"><parent link="a"/>'
                      '<child link="b"/></joint></robot>')
    with pytest.raises(ValueError, match="broken.urdf"):
        rbdgen.Robot.from_urdf(broken)
    with pytest.raises(ValueError, match="base_link|link"):
        rbdgen.Robot.from_urdf(ROBOTS / "ur5e.urdf", base_link="no_such_link")
    with pytest.raises(ValueError):
        rbdgen.Robot.from_scene(broken)


def test_results_are_new_arrays(ur5e):
    """Outputs never alias inputs or each other."""
    q = np.zeros((2, 6))
    H1, H2 = ur5e.mass_matrix(q), ur5e.mass_matrix(q)
    H1[:] = 0
    assert np.any(H2 != 0)
    assert H2.flags.c_contiguous and H2.dtype == np.float64 and H2.flags.owndata


def test_non_finite_values_of_a_threaded_batch_name_the_first_bad_state(ur5e):
    """A batch's values are checked state by state in the worker threads: the lowest bad state is named."""
    zeros, v = np.zeros((1000, 6)), np.zeros((1000, 6))
    v[700, 3], v[300, 1] = np.inf, np.nan
    for threads in (1, 2, 7):
        with pytest.raises(ValueError, match=r"inverse_dynamics: argument 'v' has a non-finite value at \[300, 1\]"):
            ur5e.inverse_dynamics(zeros, v, zeros, threads=threads)
        with pytest.raises(ValueError, match=r"forward_dynamics_derivatives: argument 'v' has a non-finite value at \[300, 1\]"):
            ur5e.forward_dynamics_derivatives(zeros, v, zeros, threads=threads)
    # the lowest state first, then the first argument: v of state 63 before q of state 64 (another block)
    q = np.zeros((1000, 6))
    q[64, 0], v[63, 5] = np.nan, np.inf
    with pytest.raises(ValueError, match=r"inverse_dynamics: argument 'v' has a non-finite value at \[63, 5\]"):
        ur5e.inverse_dynamics(q, v, zeros, threads=2)
    q[63, 2] = -np.inf
    with pytest.raises(ValueError, match=r"inverse_dynamics: argument 'q' has a non-finite value at \[63, 2\]"):
        ur5e.inverse_dynamics(q, v, zeros, threads=2)
