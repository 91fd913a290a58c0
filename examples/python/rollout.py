#!/usr/bin/env python3
"""One batched rollout: N random initial states of a bundled robot falling under gravity with joint
damping, integrated by semi-implicit Euler on batched forward dynamics, plotted with gnuplot.

    PYTHONPATH=build/python python3 examples/python/rollout.py [--robot robots/ur5e.urdf] [--states 1000]
        [--duration 2] [--dt 1e-3] [--runtime] [--threads 2] [--out rollout.png]

By default the robot is rbdgen.compile'd (generated code); --runtime uses rbdgen.Robot instead.
Writes OUT (PNG: eight rollouts' shoulder angle, the mean and the spread over the whole batch) and
OUT with .dat (the plotted data). Fixed-base robots with
revolute/prismatic joints (q and v have the same layout, so q += dt v is the exact update).
"""
import argparse
import shutil
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import rbdgen

ROOT = Path(__file__).resolve().parents[2]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--robot", default=str(ROOT / "robots" / "ur5e.urdf"))
    p.add_argument("--states", type=int, default=1000)
    p.add_argument("--duration", type=float, default=2.0)
    p.add_argument("--dt", type=float, default=1e-3)
    p.add_argument("--damping", type=float, default=0.05,
                   help="viscous joint damping, N m s/rad (explicit: stable while dt < 2 I_min / damping)")
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--runtime", action="store_true", help="rbdgen.Robot (runtime) instead of rbdgen.compile")
    p.add_argument("--out", default="rollout.png")
    args = p.parse_args()

    t0 = time.perf_counter()
    robot = rbdgen.Robot.from_urdf(args.robot) if args.runtime else rbdgen.compile(args.robot)
    print("%s: %s, nq = %d, nv = %d (%s in %.2f s)" % (robot.name, "runtime" if args.runtime else "generated",
          robot.nq, robot.nv, "loaded" if args.runtime else "compiled or cached", time.perf_counter() - t0))
    if robot.nq != robot.nv:
        sys.exit("rollout.py: this example integrates q += dt v: joints with quaternions are not handled")

    rng = np.random.default_rng(1)
    n = args.states
    q = rng.uniform(-np.pi, np.pi, (n, robot.nq))
    v = np.zeros((n, robot.nv))
    tau = np.zeros((n, robot.nv))
    steps = int(round(args.duration / args.dt))
    record = max(1, steps // 400)
    joint = min(1, robot.nq - 1)  # the shoulder of an arm
    rows = []
    t0 = time.perf_counter()
    for k in range(steps + 1):
        if k % record == 0:
            rows.append(np.r_[k * args.dt, q[:, joint].mean(), q[:, joint].std(), q[:8, joint]])
        if k == steps:
            break
        np.multiply(v, -args.damping, out=tau)  # damping torque
        a = robot.forward_dynamics(q, v, tau, threads=args.threads)
        v += args.dt * a  # semi-implicit Euler: velocity first,
        q += args.dt * v  # then the position with the new velocity
    wall = time.perf_counter() - t0
    print("%d states x %d steps: %.2f s, %.3g forward dynamics per second (threads = %d)"
          % (n, steps, wall, n * steps / wall, args.threads))

    out = Path(args.out)
    dat = out.with_suffix(".dat")
    np.savetxt(dat, np.array(rows), header="t mean std q0..q7 of joint %s" % robot.dof_names[joint])
    if shutil.which("gnuplot") is None:
        print("gnuplot not found: data written to %s, no plot" % dat)
        return
    traces = ", ".join("'%s' using 1:%d with lines lc rgb '#9090c0' notitle" % (dat, c) for c in range(4, 12))
    script = "\n".join([
        "set terminal pngcairo size 1000,600 noenhanced",
        "set output '%s'" % out,
        "set title '%s: %d rollouts from random states, joint %s (semi-implicit Euler, dt = %g s)'"
        % (robot.name, n, robot.dof_names[joint], args.dt),
        "set xlabel 't [s]'", "set ylabel 'q [rad]'", "set key top right", "set grid",
        "plot '%s' using 1:($2-$3):($2+$3) with filledcurves fc rgb '#d0e0ff' title 'mean +- std over the batch', "
        "%s, '%s' using 1:2 with lines lw 3 lc rgb '#003080' title 'mean'" % (dat, traces, dat),
    ])
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    print("plot: %s (data: %s)" % (out, dat))


if __name__ == "__main__":
    main()
