#!/usr/bin/env python3
"""Cost of calling rbdgen's generated code from Python (the README's numbers).

    PYTHONPATH=build/python python3 examples/python/timing.py [--robot robots/ur5e.urdf] [--states 100000]

1. per-call overhead: a single-state call of the compiled robot from Python (center_of_mass and
   forward_dynamics, median of repeated timeit runs) minus the same call in C++;
2. batched forward dynamics, N states in one call (threads = 1 and 2), in states per second, against
   the same generated function called in a C++ loop over the same row-major layout (fd_loop.cpp,
   compiled here with the flags of rbdgen.compile).
"""
import argparse
import subprocess
import sys
import tempfile
import timeit
from pathlib import Path

import numpy as np

import rbdgen
from rbdgen import _compile

HERE = Path(__file__).resolve().parent


def median_time(fn, number, repeat=7):
    return float(np.median(timeit.repeat(fn, number=number, repeat=repeat))) / number


def cxx_loop(robot, n):
    """states/s and ns per call of fd_loop.cpp on this robot's generated header."""
    module = _compile.module_of(robot)
    name = module.__name__
    header = Path(module.__file__).parent / name / "dynamics.hpp"
    with tempfile.TemporaryDirectory() as tmp:
        exe = Path(tmp) / "fd_loop"
        flags = [f for f in _compile.CXXFLAGS if f not in ("-shared", "-fPIC", "-fvisibility=hidden")]
        cmd = [_compile._compiler(), *flags, "-I" + _compile._config.EIGEN_INCLUDE.split(";")[0],
               '-DROBOT_HEADER="%s"' % header, "-DROBOT_NS=" + name, str(HERE / "fd_loop.cpp"), "-o", str(exe)]
        subprocess.run(cmd, check=True)
        rate, ns, _ = subprocess.run([str(exe), str(n)], check=True, capture_output=True, text=True).stdout.split()
    return float(rate), float(ns)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--robot", default=str(HERE.parents[1] / "robots" / "ur5e.urdf"))
    p.add_argument("--states", type=int, default=100000)
    args = p.parse_args()

    robot = rbdgen.compile(args.robot)
    rng = np.random.default_rng(1)
    n = args.states
    q, v, tau = (rng.uniform(-2, 2, (n, k)) for k in (robot.nq, robot.nv, robot.nv))
    q1, v1, t1 = q[0].copy(), v[0].copy(), tau[0].copy()

    com_ns = 1e9 * median_time(lambda: robot.center_of_mass(q1), 20000)
    fd_ns = 1e9 * median_time(lambda: robot.forward_dynamics(q1, v1, t1), 20000)
    rate_cxx, fd_cxx_ns = cxx_loop(robot, n)
    print("%s (nq = %d, nv = %d), generated code, -O2 -march=native" % (robot.name, robot.nq, robot.nv))
    print("single state from Python: center_of_mass %.0f ns, forward_dynamics %.0f ns per call" % (com_ns, fd_ns))
    print("forward_dynamics in a C++ loop: %.0f ns per call -> Python per-call overhead %.0f ns"
          % (fd_cxx_ns, fd_ns - fd_cxx_ns))
    for threads in (1, 2):
        t = median_time(lambda: robot.forward_dynamics(q, v, tau, threads=threads), 1, repeat=5)
        print("batched forward_dynamics from Python, N = %d, threads = %d: %.3g states/s (%.1f%% of the C++ loop's "
              "%.3g states/s on one thread)" % (n, threads, n / t, 100 * (n / t) / rate_cxx, rate_cxx))


if __name__ == "__main__":
    sys.exit(main())
