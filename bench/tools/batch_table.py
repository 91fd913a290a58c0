#!/usr/bin/env python3
"""The markdown table of bench_batch (scripts/bench.sh): states per second per core of a loop of
single-state calls, of the SIMD batch and of SIMD + 2 threads, double and float, with the ratios of
the goals (SIMD / single loop per core: >= 3x double, >= 5x float; 2 threads / 1 thread: >= 1.8x).

    batch_table.py --json bench_batch.json --text bench_batch.txt --meta meta.txt --md out.md
"""
import argparse
import json
import re

IMPLS = ["single double", "single float", "SIMD double", "SIMD float", "SIMD double 2 threads", "SIMD float 2 threads"]


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
        out[key] = (b["states/s"], b["states/s/core"])
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
               "%s repetitions (median), wall-clock time." % (meta.get("gcc", "g++"), meta.get("repetitions", "?")))
    out.append("- Each iteration evaluates N states (8192; 2048 for nv > 20) of a pool of 4N seeded random states "
               "(unit quaternions, joints and velocities in [-3, 3], third input in [-2, 2]), starting N/4 states "
               "further each time, into an N-state row-major output kept live (`benchmark::DoNotOptimize`). "
               "`single`: a loop of single-state calls (the loop a user writes); `SIMD`: one call of the batch API "
               "(`NS::batch::...`, threads = 1); `2 threads`: threads = 2 (per core: the rate / 2).")
    for r in robots_info:
        out.append("- " + r)
    out.append("")
    out.append("## States per second per core")
    out.append("")
    out.append("| robot | algorithm | single double | single float | SIMD double | SIMD float | SIMD double, 2 threads (per core) | SIMD float, 2 threads (per core) |")
    out.append("|---|---|--:|--:|--:|--:|--:|--:|")
    algos = list(dict.fromkeys(k[1] for k in cells))
    for robot in robots:
        for algo in algos:
            c = {impl: cells.get((robot, algo, impl)) for impl in IMPLS}
            if any(v is None for v in c.values()):
                continue
            sd, sf = c["single double"][1], c["single float"][1]
            vd, vf = c["SIMD double"][1], c["SIMD float"][1]
            td, tf = c["SIMD double 2 threads"], c["SIMD float 2 threads"]
            out.append("| %s | %s | %s | %s | %s (%.1f×) | %s (%.1f×) | %s (%s, %.2f× 1 thread) | %s (%s, %.2f× 1 thread) |" % (
                robot, algo, fmt(sd), fmt(sf), fmt(vd), vd / sd, fmt(vf), vf / sf,
                fmt(td[0]), fmt(td[1]), td[0] / vd, fmt(tf[0]), fmt(tf[1]), tf[0] / vf))
    out.append("")
    out.append("(SIMD ratios: against the single-state loop of the same scalar; 2 threads: total rate, per-core rate, "
               "and the total against one thread.)")
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
