#!/usr/bin/env python3
"""The markdown table of bench_batch (scripts/bench.sh): states per second per core of a loop of
single-state calls, of the SIMD batch (rows and columns layouts) and of SIMD + 2 threads, double and float, with the ratios of
the goals (SIMD / single loop per core: >= 3x double, >= 5x float; 2 threads / 1 thread: >= 1.8x).

    batch_table.py --json bench_batch.json --text bench_batch.txt --meta meta.txt --md out.md
"""
import argparse
import json
import re

IMPLS = ["single double", "single float", "SIMD double", "SIMD float", "SIMD double 1 thread", "SIMD double 2 threads",
         "SIMD float 1 thread", "SIMD float 2 threads", "SIMD double columns", "SIMD float columns"]
THREADS = ["SIMD double 1 thread", "SIMD double 2 threads", "SIMD float 1 thread", "SIMD float 2 threads"]


def medians(path):
    """{(robot, algorithm, impl): (states/s, states/s per core)} (medians when repeated)."""
    data = json.load(open(path))
    out, seen_median = {}, set()
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        name = b.get("run_name", b["name"])
        robot, algo, impl = name.split("/")[:3]
        key = (robot, algo, impl)
        if b.get("run_type") == "aggregate":
            seen_median.add(key)
        elif key in seen_median:
            continue
        out[key] = (b["states/s"], b["states/s/core"], int(b["N"]), b["states/cpu-s"])
    return out, data.get("context", {})


def fmt(x):
    if x >= 1e6:
        return "%.2fM" % (x / 1e6)
    return "%.0fk" % (x / 1e3)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--json", required=True)
    p.add_argument("--text", help="bench_batch's stdout (robot and check lines)")
    p.add_argument("--meta", help="key=value lines (cpu, date, gcc, ...)")
    p.add_argument("--md", required=True)
    a = p.parse_args()
    cells, context = medians(a.json)
    meta = {}
    if a.meta:
        for line in open(a.meta):
            if "=" in line:
                k, v = line.rstrip("\n").split("=", 1)
                meta[k] = v
    lines = [l.rstrip("\n") for l in open(a.text)] if a.text else []
    robots_info = [l for l in lines if l.startswith("robot ")]
    checks = [l for l in lines if l.startswith("check ")]
    robots = list(dict.fromkeys(k[0] for k in cells))
    out = ["# rbdgen batches: SIMD and threads — %s" % meta.get("date", context.get("date", "")), ""]
    out.append("- CPU: **%s** (%s cores, shared with other jobs)" % (meta.get("cpu", "?"), meta.get("cores", context.get("num_cpus", "?"))))
    out.append("- Compiler: %s, `-O3 -march=native` (packs of the native width, below); bench/batch, Google Benchmark, "
               "%s repetitions (median)." % (meta.get("gcc", "g++"), meta.get("repetitions", "?")))
    out.append("- Each iteration evaluates N states of a pool of 32768 seeded random states (unit quaternions, joints "
               "and velocities in [-3, 3], third input in [-2, 2]), starting N/4 states further each time, into an "
               "N-state row-major output kept live (`benchmark::DoNotOptimize`). `single`: a loop of single-state "
               "calls (the loop a user writes); `SIMD`: one call of the batch API (`NS::batch::...`).")
    out.append("- Per core, in cache: N such that a call's inputs and outputs fit in 512 KB (N in the table), "
               "CPU time: the speed of the code, not of the memory. Threads: N = 8192 (2048 for nv > 20), "
               "wall-clock time, 1 and 2 threads (the cores are shared with other jobs: the scaling is a lower "
               "bound).")
    for r in robots_info:
        out.append("- " + r)
    out.append("")
    out.append("## States per second per core (in cache)")
    out.append("")
    out.append("| robot | algorithm | N | single double | single float | SIMD double | SIMD float | SIMD double, columns "
               "| SIMD float, columns |")
    out.append("|---|---|--:|--:|--:|--:|--:|--:|--:|")
    algos = list(dict.fromkeys(k[1] for k in cells))
    rows = [(robot, algo, {impl: cells.get((robot, algo, impl)) for impl in IMPLS}) for robot in robots for algo in algos]
    rows = [r for r in rows if all(v is not None for v in r[2].values())]
    for robot, algo, c in rows:
        sd, sf, vd, vf, cd, cf = (c[i][1] for i in IMPLS[:4] + IMPLS[8:])
        out.append("| %s | %s | %d | %s | %s | %s (%.1f×) | %s (%.1f×) | %s (%.1f×) | %s (%.1f×) |" % (
            robot, algo, c["SIMD double"][2], fmt(sd), fmt(sf), fmt(vd), vd / sd, fmt(vf), vf / sf, fmt(cd), cd / sd,
            fmt(cf), cf / sf))
    out.append("")
    out.append("(×: the SIMD batch against the single-state loop of the same scalar. SIMD: the arrays in the default "
               "`Layout::rows` (N × item, as the single-state loop); columns: `Layout::columns` (item × N, structure of "
               "arrays: no transposition between the states' rows and the packs).)")
    out.append("")
    out.append("## Threads (many states per call)")
    out.append("")
    out.append("| robot | algorithm | N | SIMD double, 1 thread | 2 threads (per core) | scaling | CPU efficiency | "
               "SIMD float, 1 thread | 2 threads (per core) | scaling | CPU efficiency |")
    out.append("|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    for robot, algo, c in rows:
        d1, d2, f1, f2 = (c[i] for i in THREADS)
        out.append("| %s | %s | %d | %s | %s (%s) | %.2f× | %.2f | %s | %s (%s) | %.2f× | %.2f |" % (
            robot, algo, d1[2], fmt(d1[0]), fmt(d2[0]), fmt(d2[1]), d2[0] / d1[0], d2[3] / d1[3], fmt(f1[0]), fmt(f2[0]),
            fmt(f2[1]), f2[0] / f1[0], f2[3] / f1[3]))
    out.append("")
    out.append("(scaling: wall-clock rate with 2 threads / 1 thread; CPU efficiency: states per CPU second of the "
               "process (all threads) with 2 threads / with 1 thread, 1.00 when the second thread adds no work: then "
               "2 free cores give 2×.)")
    out.append("")
    if checks:
        out.append("")
        out.append("## Agreement (checked at start-up, 256 states)")
        out.append("")
        out.append("max |batch - single| / max(1, max |single|) per state, against the single-state double code:")
        out.append("")
        for c in checks:
            m = re.match(r"check (.*?): (SIMD .*)", c)
            out.append("- %s: %s" % (m.group(1), m.group(2)) if m else "- " + c)
    open(a.md, "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
