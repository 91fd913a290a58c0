#!/usr/bin/env python3
"""Merge the outputs of scripts/bench.sh into one table (markdown + CSV).

Inputs (in --raw DIR): gcc_<robot>.json and clang_<robot>.json (Google Benchmark, medians of the
repetitions), costs.csv (bench_costs), callgrind.csv (robot,algo,instructions per call),
meta.txt (key=value lines: cpu, gcc, clang, date, compile times...). Outputs: --md, --csv, and
with --pinocchio-md the rbdgen vs Pinocchio table (Pinocchio timed in the same programs, g++ and
clang++). Time = cpu_time of the median repetition, ns per call.
"""
import argparse
import csv
import glob
import json
import os

ALGOS = ["fk", "fk_vel", "id", "id_fext", "gravity", "nle", "mass_matrix", "fd", "fd_aba", "fd_crba", "jacobian", "jacobian_kin", "com",
         "id_derivatives", "fd_derivatives"]
ALGO_TITLES = {
    "fk": "FK, all links", "fk_vel": "FK + velocities", "id": "inverse dynamics",
    "id_fext": "inverse dynamics with a wrench on every link", "gravity": "gravity torques",
    "nle": "nonlinear effects", "mass_matrix": "mass matrix", "fd": "forward dynamics (default)",
    "fd_aba": "forward dynamics ABA", "fd_crba": "forward dynamics CRBA+LTDL", "jacobian": "Jacobian (last moving link)",
    "jacobian_kin": "Jacobian via kinematics(q) (the former jacobian(body, q))",
    "com": "centre of mass", "id_derivatives": "ID derivatives (dtau/dq, dtau/dalpha)",
    "fd_derivatives": "FD derivatives (dalphaD/dq, dalphaD/dalpha, H^-1)"}
# peers time one forward-dynamics algorithm: compare every forward-dynamics row with it
PEER_ALGO = {"fd_aba": "fd", "fd_crba": "fd"}
PEERS = ["kdl", "mujoco", "pinocchio"]
# the rbdgen vs Pinocchio table: our row -> what Pinocchio computes for it
PIN_ALGOS = ["fk", "id", "mass_matrix", "fd", "jacobian", "id_derivatives", "fd_derivatives"]
PIN_TITLES = {
    "fk": "FK, all links | `forwardKinematics` + `updateFramePlacements`",
    "id": "inverse dynamics | `rnea`",
    "mass_matrix": "mass matrix | `crba` (+ lower triangle)",
    "fd": "forward dynamics (default) | `aba`",
    "jacobian": "Jacobian (last moving link) | `computeJointJacobian` (+ rotation to world axes)",
    "id_derivatives": "ID derivatives | `computeRNEADerivatives`",
    "fd_derivatives": "FD derivatives | `computeABADerivatives`"}
THRESHOLD = 3.0


def load_json(path):
    with open(path) as f:
        data = json.load(f)
    times = {}
    for b in data.get("benchmarks", []):
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        name = b.get("run_name", b["name"])
        robot, algo, impl = name.split("/")[:3]
        scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
        times[(robot, algo, impl)] = b["cpu_time"] * scale
    return data.get("context", {}), times


def fmt_ns(v):
    if v is None:
        return "n/a"
    return f"{v:,.0f}" if v >= 100 else f"{v:.1f}"


def fmt_ratio(v):
    if v is None:
        return "–"
    flag = " ⚠" if v < THRESHOLD else ""
    return f"{v:.1f}×{flag}"


def pinocchio_table(robots, contexts, get, robot_title, meta):
    """rbdgen vs Pinocchio, per compiler: both measured in the same program on the same states."""
    out = [f"# rbdgen vs Pinocchio — {meta.get('date', '?')}\n"]
    pin = next((contexts[r].get("peer/pinocchio") for r in robots if contexts.get(r, {}).get("peer/pinocchio")), "not built")
    out.append(f"- CPU: **{meta.get('cpu', '?')}** ({meta.get('cores', '?')} cores, shared with other jobs: "
               "differences under 1.3× are noise)")
    out.append(f"- g++: {meta.get('gcc', '?')}; clang++: {meta.get('clang', '?')}; `-O3 -march=native -DNDEBUG` for "
               "everything, Pinocchio included (header-only, compiled into the same bench program)")
    out.append(f"- {pin}")
    out.append(f"- Google Benchmark, {meta.get('repetitions', '?')} repetitions (median), min time "
               f"{meta.get('min_time', '?')} s, CPU time; every iteration takes the next of 256 seeded random states, "
               "the same for every implementation (Pinocchio's q, v, a, tau are the same states in its layout: "
               "quaternion [x y z w] after the position, free-flyer velocity [v; ω], dofs in the same order); "
               "results kept live with `benchmark::DoNotOptimize`.")
    out.append("- A Pinocchio cell is timed only if its results agree with the runtime (FK, ID, H, Jacobian to 1e-9 "
               "relative; ABA to 1e-12 × cond(H); derivatives against the runtime's derivatives in long double, "
               "1e-9 and 1e-12 × cond(H)): see the agreement table of the main results file.")
    out.append("- gen = the generated function (double); runtime = rbdgen's generic runtime (`rbd::`), which starts "
               "from a `MultiBodyConfig` and runs `forwardKinematics` + `forwardVelocity` first. Ratio = Pinocchio / "
               "gen with the same compiler (> 1: rbdgen faster); ⚠ = below 3×.\n")
    out.append("| robot (nv) | algorithm | Pinocchio call | gen g++ | Pinocchio g++ | **Pinocchio / gen g++** | "
               "gen clang | Pinocchio clang | **Pinocchio / gen clang** | runtime g++ | Pinocchio / runtime g++ |")
    out.append("|---|---|---|--:|--:|--:|--:|--:|--:|--:|--:|")
    for robot in robots:
        for algo in PIN_ALGOS:
            pg, pc = get(robot, algo, "pinocchio", "gcc"), get(robot, algo, "pinocchio", "clang")
            gg, gc = get(robot, algo, "gen_double", "gcc"), get(robot, algo, "gen_double", "clang")
            rt = get(robot, algo, "runtime", "gcc")
            if not any((pg, pc, gg, gc)):
                continue
            ratio = lambda a, b: fmt_ratio(a / b) if a and b else "–"
            out.append(f"| {robot_title(robot)} | {PIN_TITLES[algo]} | {fmt_ns(gg)} | {fmt_ns(pg)} | {ratio(pg, gg)} | "
                       f"{fmt_ns(gc)} | {fmt_ns(pc)} | {ratio(pc, gc)} | {fmt_ns(rt)} | "
                       f"{fmt_ratio(pg / rt).replace(' ⚠', '') if pg and rt else '–'} |")
    out.append("")
    out.append("## Agreement of Pinocchio with the runtime\n")
    out.append("| robot | " + " | ".join(PIN_ALGOS) + " |")
    out.append("|---|" + "---|" * len(PIN_ALGOS))
    for robot in robots:
        ctx = contexts.get(robot, {})
        cells = []
        for algo in PIN_ALGOS:
            v = ctx.get(f"check/pinocchio/{algo}")
            if v is None:
                cells.append("n/a")
                continue
            err, status = v.split(" ")[:2]
            cells.append(err if status == "ok" else f"**{err} DISAGREES: not timed**")
        out.append(f"| {robot} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--raw", required=True)
    ap.add_argument("--md", required=True)
    ap.add_argument("--csv", required=True)
    ap.add_argument("--pinocchio-md", help="also write the rbdgen vs Pinocchio table here")
    args = ap.parse_args()

    meta = {}
    meta_path = os.path.join(args.raw, "meta.txt")
    if os.path.exists(meta_path):
        for line in open(meta_path):
            if "=" in line:
                k, v = line.rstrip("\n").split("=", 1)
                meta[k] = v

    robots, contexts, t = [], {}, {}
    for compiler in ("gcc", "clang"):
        for path in sorted(glob.glob(os.path.join(args.raw, f"{compiler}_*.json"))):
            ctx, times = load_json(path)
            robot = ctx.get("robot") or os.path.basename(path)[len(compiler) + 1:-5]
            if robot not in robots:
                robots.append(robot)
            if compiler == "gcc" or robot not in contexts:
                contexts[robot] = ctx
            for (r, algo, impl), v in times.items():
                t[(r, algo, impl, compiler)] = v
    order = ["ur5e", "ur5", "iiwa7", "panda_arm", "panda", "quadruped", "solo12", "humanoid", "talos_reduced"]
    robots.sort(key=lambda r: (order.index(r) if r in order else len(order), r))

    costs = {}
    costs_path = os.path.join(args.raw, "costs.csv")
    if os.path.exists(costs_path):
        for row in csv.DictReader(open(costs_path)):
            costs[(row["robot"], row["algo"])] = row
    instr = {}
    cg_path = os.path.join(args.raw, "callgrind.csv")
    if os.path.exists(cg_path):
        for row in csv.DictReader(open(cg_path)):
            instr[(row["robot"], row["algo"])] = float(row["instructions"])

    def get(robot, algo, impl, compiler="gcc"):
        return t.get((robot, algo, impl, compiler))

    def robot_title(robot):
        ctx = contexts.get(robot, {})
        return f"{robot} ({ctx.get('nv', '?')}{' +free' if ctx.get('floating') == 'yes' else ''})"

    rows = []
    for robot in robots:
        for algo in ALGOS:
            g = get(robot, algo, "gen_double", "gcc")
            c = get(robot, algo, "gen_double", "clang")
            floats = [v for v in (get(robot, algo, "gen_float", "gcc"), get(robot, algo, "gen_float", "clang")) if v]
            f = min(floats) if floats else None
            rt = get(robot, algo, "runtime", "gcc")
            peers = {p: get(robot, PEER_ALGO.get(algo, algo), p, "gcc") for p in PEERS}
            best_peer = min([v for v in peers.values() if v], default=None)
            # KDL and MuJoCo are Debian's binaries (timed in the g++ run only); Pinocchio is compiled
            # into each program, so the clang++ ratio takes its clang++ time when there is one
            pin_clang = get(robot, PEER_ALGO.get(algo, algo), "pinocchio", "clang")
            peers_clang = dict(peers, pinocchio=pin_clang or peers["pinocchio"])
            best_peer_clang = min([v for v in peers_clang.values() if v], default=None)
            gens = [v for v in (g, c) if v]
            worst_gen = max(gens) if gens else None
            rows.append({
                "robot": robot, "algo": algo, "gen_gcc": g, "gen_clang": c, "gen_float": f, "runtime": rt,
                "kdl": peers["kdl"], "mujoco": peers["mujoco"], "pinocchio": peers["pinocchio"],
                "peer_over_gen_gcc": best_peer / g if best_peer and g else None,
                "peer_over_gen_clang": best_peer_clang / c if best_peer_clang and c else None,
                "runtime_over_gen": rt / worst_gen if rt and worst_gen else None,
            })

    out = []
    out.append(f"# rbdgen benchmark — {meta.get('date', '?')}\n")
    out.append(f"- CPU: **{meta.get('cpu', '?')}** ({meta.get('cores', '?')} cores, shared: differences under 1.3× are noise)")
    out.append(f"- g++: {meta.get('gcc', '?')}; clang++: {meta.get('clang', '?')}; flags `-O3 -march=native -DNDEBUG` (Release)")
    out.append(f"- Peers: {meta.get('peers', '?')}")
    out.append(f"- Method: Google Benchmark, {meta.get('repetitions', '?')} repetitions (median shown), min time "
               f"{meta.get('min_time', '?')} s per repetition, CPU time; each iteration takes the next of 256 seeded "
               "random states (unit quaternions; joints in [-3, 3], velocities, accelerations, torques in [-2, 2]); "
               "results kept live with `benchmark::DoNotOptimize`.")
    out.append("- Every cell includes what it needs from q (forward kinematics, velocities): runtime = "
               "`forwardKinematics` (+ `forwardVelocity`) + the algorithm on a `MultiBodyConfig`; MuJoCo = "
               "`mj_kinematics` + `mj_comPos` (+ `mj_comVel`) + the algorithm, inputs copied into `mjData`; "
               "KDL = one solver call. Generated = one call of the generated function (`body_velocities` for FK + "
               "velocities, `jacobian(body, q)` and `center_of_mass(q)` from q).")
    out.append("- Peers are timed only where they agree with the runtime (agreement table below). Forward dynamics "
               "rows compare with each peer's one forward-dynamics call (KDL `ChainFdSolver_RNE`, MuJoCo `mj_forward` "
               "with constraints/contacts/passive forces disabled).")
    out.append(f"- Ratios: best peer / generated (per compiler), runtime / slower generated; ⚠ = below {THRESHOLD:.0f}×. "
               "The Pinocchio column is its g++ time; the clang++ ratio uses Pinocchio's clang++ time when it was run.\n")
    out.append("## Time per call (ns)\n")
    out.append("| robot (nv) | algorithm | gen double g++ | gen double clang | gen float | runtime | KDL | MuJoCo | Pinocchio | best peer / gen g++ | best peer / gen clang | runtime / gen |")
    out.append("|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    for r in rows:
        if not any(r[k] for k in ("gen_gcc", "gen_clang", "gen_float", "runtime", "kdl", "mujoco", "pinocchio")):
            continue  # e.g. derivatives in a run without them
        out.append(f"| {robot_title(r['robot'])} | {ALGO_TITLES[r['algo']]} | {fmt_ns(r['gen_gcc'])} | {fmt_ns(r['gen_clang'])} | "
                   f"{fmt_ns(r['gen_float'])} | {fmt_ns(r['runtime'])} | {fmt_ns(r['kdl'])} | {fmt_ns(r['mujoco'])} | "
                   f"{fmt_ns(r['pinocchio'])} | {fmt_ratio(r['peer_over_gen_gcc'])} | {fmt_ratio(r['peer_over_gen_clang'])} | "
                   f"{fmt_ratio(r['runtime_over_gen'])} |")
    misses = [r for r in rows if any(v is not None and v < THRESHOLD for v in (r["peer_over_gen_gcc"], r["peer_over_gen_clang"]))]
    out.append(f"\nCells below {THRESHOLD:.0f}× the best peer: {len(misses)} of "
               f"{sum(1 for r in rows if r['peer_over_gen_gcc'] is not None)} with a peer.\n")

    out.append("## Which link, which algorithm\n")
    out.append("| robot | Jacobian link | generated forward_dynamics() | KDL | MuJoCo | Pinocchio |")
    out.append("|---|---|---|---|---|---|")
    for robot in robots:
        ctx = contexts.get(robot, {})
        out.append(f"| {robot} | {ctx.get('jacobian_body', '?')} | {ctx.get('fd_algorithm', '?').split(' (')[0]} | "
                   f"{ctx.get('peer/kdl', 'not built')} | {ctx.get('peer/mujoco', 'not built')} | "
                   f"{ctx.get('peer/pinocchio', 'not built')} |")

    out.append("\n## Agreement with the runtime (max relative error over 8 states; FD of the generated code: error / cond(H))\n")
    out.append("Derivatives: against the runtime's analytic derivatives in long double (`runtime_ld`, itself checked "
               "against long double central differences), over 4 states; FD derivatives: error / cond(H).\n")
    impls = ["gen_double", "gen_float", "runtime", "runtime_ld", "kdl", "mujoco", "pinocchio"]
    out.append("| robot | implementation | " + " | ".join(ALGOS) + " |")
    out.append("|---|---|" + "---|" * len(ALGOS))
    for robot in robots:
        ctx = contexts.get(robot, {})
        for impl in impls:
            cells = []
            any_check = False
            for algo in ALGOS:
                v = ctx.get(f"check/{impl}/{algo}")
                if v is None:
                    cells.append("n/a")
                else:
                    any_check = True
                    err, status = v.split(" ")[:2]
                    if status == "ok":
                        cells.append(err)
                    elif status.startswith("DIFFERS"):
                        cells.append(f"{err} (model changed: not timed)")
                    else:
                        cells.append(f"**{err} DISAGREES: not timed**")
            if any_check:
                out.append(f"| {robot} | {impl} | " + " | ".join(cells) + " |")

    if costs:
        out.append("\n## Cost model: emitted operations vs Featherstone, instructions per call\n")
        out.append("Emitted = operations in the generated function after constant folding and dead-code removal "
                   "(mults, adds; calls = sin/cos/sqrt/divisions, of which sin+cos). Featherstone's counts are for an "
                   "unbranched chain of n revolute joints (RNEA (93n−69)m+(81n−66)a, CRBA (10n²+22n−32)m+(6n²+37n−43)a, "
                   "ABA (224n−259)m+(205n−248)a); for branched or floating robots they are given with n = nv as an "
                   "indication. Instructions per call: `valgrind --tool=callgrind` on `callgrind_<robot>` "
                   "(g++, `-O3 -march=native -mno-avx512f`), (I(2N) − I(N)) / N.\n")
        out.append("| robot (nv) | algorithm | mults | adds | calls (sin+cos) | Featherstone m | Featherstone a | emitted / Featherstone (m+a) | instructions / call | ns gen g++ |")
        out.append("|---|---|--:|--:|--:|--:|--:|--:|--:|--:|")
        for robot in robots:
            for algo in ALGOS:
                c = costs.get((robot, algo)) or (costs.get((robot, "fd_crba" if contexts.get(robot, {}).get("fd_algorithm", "").startswith("CRBA") else "fd_aba")) if algo == "fd" else None)
                if not c:
                    continue
                fm, fa = c["feather_mults"], c["feather_adds"]
                ratio = f"{(int(c['mults']) + int(c['adds'])) / (int(fm) + int(fa)):.2f}" if fm and fa else ""
                ins = instr.get((robot, algo))
                out.append(f"| {robot} ({c['nv']}) | {ALGO_TITLES[algo]} | {c['mults']} | {c['adds']} | {c['calls']} ({c['sincos']}) | "
                           f"{fm} | {fa} | {ratio} | {f'{ins:,.0f}' if ins is not None else 'n/a'} | {fmt_ns(get(robot, algo, 'gen_double'))} |")

    if "compile_gcc" in meta or "compile_clang" in meta:
        out.append("\n## Compile time\n")
        out.append(f"{meta.get('compile_what', '')}: g++ **{meta.get('compile_gcc', '?')} s**, clang++ "
                   f"**{meta.get('compile_clang', '?')} s** (target < 30 s).")
    text = "\n".join(out) + "\n"
    with open(args.md, "w") as f:
        f.write(text)
    if args.pinocchio_md:
        with open(args.pinocchio_md, "w") as f:
            f.write(pinocchio_table(robots, contexts, get, robot_title, meta))

    with open(args.csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["robot", "nv", "algo", "gen_double_gcc_ns", "gen_double_clang_ns", "gen_float_ns", "runtime_ns",
                    "kdl_ns", "mujoco_ns", "pinocchio_ns", "best_peer_over_gen_gcc", "best_peer_over_gen_clang", "runtime_over_gen",
                    "mults", "adds", "calls", "instructions"])
        for r in rows:
            c = costs.get((r["robot"], r["algo"]), {})
            w.writerow([r["robot"], contexts.get(r["robot"], {}).get("nv", ""), r["algo"]] +
                       ["" if r[k] is None else f"{r[k]:.4g}" for k in ("gen_gcc", "gen_clang", "gen_float", "runtime", "kdl", "mujoco",
                                                                        "pinocchio", "peer_over_gen_gcc", "peer_over_gen_clang", "runtime_over_gen")] +
                       [c.get("mults", ""), c.get("adds", ""), c.get("calls", ""),
                        "" if (r["robot"], r["algo"]) not in instr else f"{instr[(r['robot'], r['algo'])]:.0f}"])
    print(text)


if __name__ == "__main__":
    main()
