#!/usr/bin/env python3
"""Cost of calling rbdgen's generated code from Python (the README's numbers).

    PYTHONPATH=build/python python3 examples/python/timing.py [--robot robots/ur5e.urdf] [--states 100000]

1. per-call overhead: a single-state call of the compiled robot from Python (center_of_mass,
   forward_dynamics, forward_dynamics_derivatives; best of repeated timeit runs) minus the same
   forward_dynamics call in C++;
2. batched forward dynamics, N states in one call (threads = 1 and 2), in states per second, against
   the same generated code in C++ over the same row-major layout (fd_loop.cpp, compiled here with the
   flags of rbdgen.compile), one thread: one call of the batch API NS/batch.hpp (SIMD packs: what a
   batched Python call runs), and a loop of single-state calls.
Times are CPU times of the calling thread (time.thread_time, CLOCK_THREAD_CPUTIME_ID in C++; with
threads = 1 the batch runs on the calling thread), the best of several runs, the Python and C++ runs
interleaved: on a machine shared with other jobs, wall-clock times also count the time the process
waits for a core. The two-thread batch is timed by the wall clock (its second thread's CPU time is
elsewhere): only meaningful on idle cores.
"""
import argparse
import subprocess
import sys
import tempfile
import time
import timeit
from pathlib import Path

import numpy as np

import rbdgen
from rbdgen import _compile

HERE = Path(__file__).resolve().parent


def best_time(fn, number, repeat=7):
    return min(timeit.repeat(fn, timer=time.thread_time, number=number, repeat=repeat)) / number


def build_cxx_loop(robot, tmp):
    """fd_loop.cpp on this robot's generated headers, compiled with rbdgen.compile's flags."""
    module = _compile.module_of(robot)
    name = module.__name__
    header = Path(module.__file__).parent / name / "batch.hpp"
    exe = Path(tmp) / "fd_loop"
    flags = [f for f in _compile.CXXFLAGS if f not in ("-shared", "-fPIC", "-fvisibility=hidden")]
    cmd = [_compile._compiler(), *flags, "-I" + _compile._config.EIGEN_INCLUDE.split(";")[0],
           "-I" + _compile._config.XSIMD_INCLUDE, '-DROBOT_HEADER="%s"' % header, "-DROBOT_NS=" + name,
           str(HERE / "fd_loop.cpp"), "-o", str(exe), "-pthread"]
    subprocess.run(cmd, check=True)
    return exe


def cxx_loop(exe, n, runs=5):
    """(states/s, ns per call) of the best of `runs` loops of single-state calls over n states, and
    the states/s of the best batch call."""
    rate, ns, batch, _ = subprocess.run([str(exe), str(n), str(runs)], check=True, capture_output=True,
                                        text=True).stdout.split()
    return float(rate), float(ns), float(batch)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--robot", default=str(HERE.parents[1] / "robots" / "ur5e.urdf"))
    p.add_argument("--states", type=int, default=100000)
    p.add_argument("--rounds", type=int, default=4, help="interleaved rounds of Python and C++ runs")
    args = p.parse_args()

    robot = rbdgen.compile(args.robot)
    rng = np.random.default_rng(1)
    n = args.states
    q, v, tau = (rng.uniform(-2, 2, (n, k)) for k in (robot.nq, robot.nv, robot.nv))
    q1, v1, t1 = q[0].copy(), v[0].copy(), tau[0].copy()

    with tempfile.TemporaryDirectory() as tmp:
        exe = build_cxx_loop(robot, tmp)
        py = {1: 0.0, 2: 0.0}  # best states/s per thread count
        cxx, cxx_ns, cxx_batch = 0.0, float("inf"), 0.0
        single = {"center_of_mass": float("inf"), "forward_dynamics": float("inf"),
                  "forward_dynamics_derivatives": float("inf")}
        calls = {"center_of_mass": lambda: robot.center_of_mass(q1),
                 "forward_dynamics": lambda: robot.forward_dynamics(q1, v1, t1),
                 "forward_dynamics_derivatives": lambda: robot.forward_dynamics_derivatives(q1, v1, t1)}
        for _ in range(args.rounds):
            for threads in py:
                clock = time.thread_time if threads == 1 else time.perf_counter
                for _ in range(3):
                    t0 = clock()
                    robot.forward_dynamics(q, v, tau, threads=threads)
                    py[threads] = max(py[threads], n / (clock() - t0))
            rate, ns, batch = cxx_loop(exe, n)
            cxx, cxx_ns, cxx_batch = max(cxx, rate), min(cxx_ns, ns), max(cxx_batch, batch)
            for name, call in calls.items():
                single[name] = min(single[name], 1e9 * best_time(call, 20000, repeat=3))

    print("%s (nq = %d, nv = %d), generated code, -O2 -march=native" % (robot.name, robot.nq, robot.nv))
    print("single state from Python: " + ", ".join("%s %.0f ns" % kv for kv in single.items()) + " per call")
    print("forward_dynamics in a C++ loop: %.0f ns per call -> Python per-call overhead %.0f ns"
          % (cxx_ns, single["forward_dynamics"] - cxx_ns))
    print("forward_dynamics over N = %d states in C++, one thread: %.3g states/s by the batch API (SIMD), "
          "%.3g states/s by a loop of single-state calls" % (n, cxx_batch, cxx))
    for threads, rate in py.items():
        print("batched forward_dynamics from Python, N = %d, threads = %d: %.3g states/s (%s; %.1f%% of the C++ "
              "batch call on one thread, %.2fx the C++ loop)"
              % (n, threads, rate, "CPU time" if threads == 1 else "wall clock", 100 * rate / cxx_batch, rate / cxx))


if __name__ == "__main__":
    sys.exit(main())
