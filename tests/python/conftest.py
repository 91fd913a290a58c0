"""Shared helpers of the Python tests (run by ctest's python_tests with PYTHONPATH at the build's package)."""
import os
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
ROBOTS = Path(os.environ.get("RBDGEN_ROBOTS_DIR", ROOT / "robots"))
SCENES = Path(os.environ.get("RBDGEN_SCENES_DIR", ROOT / "scenes"))


def random_states(robot, n, seed, floating=False):
    """n random (q, v, a) of a robot whose joints are revolute/prismatic (+ a free base when floating):
    joint values in [-3, 3], unit quaternions for the base, velocities and accelerations in [-2, 2]."""
    rng = np.random.default_rng(seed)
    q = rng.uniform(-3, 3, (n, robot.nq))
    if floating:
        quat = rng.normal(size=(n, 4))
        q[:, :4] = quat / np.linalg.norm(quat, axis=1, keepdims=True)
    v = rng.uniform(-2, 2, (n, robot.nv))
    a = rng.uniform(-2, 2, (n, robot.nv))
    return q, v, a


def rel_err(x, ref):
    """max |x - ref| / max(1, max |ref|), the bound used by the C++ tests of the generated code."""
    ref = np.asarray(ref)
    return float(np.max(np.abs(np.asarray(x) - ref)) / max(1.0, float(np.max(np.abs(ref)))))


def unpack_mass_matrix(robot, packed):
    """The mass matrix (nv, nv), or (N, nv, nv) for a batch, from mass_matrix_packed's values and
    mass_matrix_entries (each entry and its mirror; every other entry 0)."""
    e = robot.mass_matrix_entries
    H = np.zeros(packed.shape[:-1] + (robot.nv, robot.nv))
    H[..., e[:, 0], e[:, 1]] = packed
    H[..., e[:, 1], e[:, 0]] = packed
    return H


# A robot of rbdgen.compile evaluates a batch on SIMD packs (NS/batch.hpp), a single state with the
# single-state function: each lane does the same operations, bitwise equal when the compiler does not
# fuse a*b + c; with FMA (the modules' -march=native on a CPU with FMA) it fuses them differently in
# the two, and they agree within SIMD_BOUND relative, grown by cond(H) for forward dynamics (README,
# "Batches: SIMD and threads"; tests/batch/test_batch.cpp).
SIMD_BOUND = 1e-13


def simd_growth(robot, q):
    """max(1, cond(H) / 1e3) for one state q: how forward dynamics' rounding differences grow."""
    return max(1.0, float(np.linalg.cond(robot.mass_matrix(q))) / 1e3)


def assert_simd_close(batch_item, single, grow=1.0):
    """One state of a compiled robot's batch against its single-state call (SIMD_BOUND)."""
    assert rel_err(batch_item, single) <= SIMD_BOUND * grow, (rel_err(batch_item, single), grow)


@pytest.fixture(scope="session")
def robots():
    return ROBOTS


@pytest.fixture(scope="session")
def scenes():
    return SCENES
