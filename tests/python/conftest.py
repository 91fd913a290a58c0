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


@pytest.fixture(scope="session")
def robots():
    return ROBOTS


@pytest.fixture(scope="session")
def scenes():
    return SCENES
