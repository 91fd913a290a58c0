#!/usr/bin/env bash
# Benchmark the generated code against the runtime, KDL, MuJoCo and optionally Pinocchio (issues 4, 15), g++ and clang++.
#
#   scripts/bench.sh [--quick] [--robots "ur5e panda"] [--build-dir DIR] [--no-callgrind] [--no-compile-time] [--no-build]
#                    [--pinocchio PINOCCHIO_SOURCE_DIR]
#   (BENCH_GCC_DIR / BENCH_CLANG_DIR override DIR/gcc and DIR/clang)
#
# Installs what is missing (scripts/install-deps.sh + clang, valgrind, KDL, kdl_parser, MuJoCo),
# configures DIR/gcc and DIR/clang (default DIR: build-bench) with -DRBDGEN_BUILD_BENCH=ON
# -DRBDGEN_BUILD_TESTS=OFF -march=native, builds, runs every bench_<robot> (the g++ build: all
# implementations; the clang++ build: the generated code only), the cost model (bench_costs),
# callgrind instruction counts, the compile time of talos_reduced's header and of every robot's header at g++ -O2
# (bench/tools/header_costs.sh: lines, seconds, peak MB -> bench/results/latest-headers.md), then writes
#   bench/results/<date>-<cpu>.md, .csv, bench/results/latest.md (and prints the table), and the
#   batch table of bench_batch (SIMD and threads): <date>-<cpu>-batch.md, latest-batch.md.
# Exit status: non-zero if a build fails or an implementation disagrees with the runtime.
# --quick: one repetition, short runs, no callgrind, no compile time (a smoke run).
# --pinocchio DIR: Pinocchio's source tree (e.g. v3.7.0; header-only, see bench/CMakeLists.txt) as one
#   more peer, timed in both builds (g++ and clang++), and libboost-dev installed; also writes
#   bench/results/<date>-<cpu>-pinocchio.md and latest-pinocchio.md (rbdgen vs Pinocchio per compiler).
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
build="$repo/build-bench"
robots=""
quick=0
callgrind=1
compile_time=1
build_step=1
pinocchio=""
repetitions=3
min_time=0.05
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1; callgrind=0; compile_time=0; repetitions=1; min_time=0.01 ;;
    --robots) robots="$2"; shift ;;
    --build-dir) build="$2"; shift ;;
    --no-callgrind) callgrind=0 ;;
    --no-compile-time) compile_time=0 ;;
    --no-build) build_step=0 ;;
    --pinocchio) pinocchio="$(cd "$2" && pwd)"; shift ;;
    -h|--help) sed -n 2,19p "$0"; exit 0 ;;
    *) echo "bench.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
  shift
done

extra=()
[ -n "$pinocchio" ] && extra=(libboost-dev) # Pinocchio's headers use Boost's (variant, fusion, mpl)
"$repo/scripts/install-deps.sh" clang valgrind liborocos-kdl-dev libkdl-parser-dev libmujoco-dev python3 "${extra[@]}"

jobs="$(nproc)"
only=()
[ -n "$robots" ] && only=("-DRBDGEN_BENCH_ONLY=${robots// /;}")
declare -A dir=([gcc]="${BENCH_GCC_DIR:-$build/gcc}" [clang]="${BENCH_CLANG_DIR:-$build/clang}")
for cc in gcc clang; do
  if [ $cc = gcc ]; then cxx=g++; targets=bench_all; else cxx=clang++; targets=bench_programs; fi
  compiler=()
  [ -f "${dir[$cc]}/CMakeCache.txt" ] || compiler=(-DCMAKE_CXX_COMPILER=$cxx) # set once: changing it wipes the cache
  # -Werror off: g++ 12 gives false -Warray-bounds / -Wmaybe-uninitialized in Eigen with AVX-512.
  cmake -S "$repo" -B "${dir[$cc]}" -G Ninja -DCMAKE_BUILD_TYPE=Release "${compiler[@]}" \
        -DCMAKE_CXX_FLAGS=-march=native -DRBDGEN_BUILD_BENCH=ON -DRBDGEN_BUILD_TESTS=OFF -DRBDGEN_WERROR=OFF \
        -DRBDGEN_PINOCCHIO_SOURCE_DIR="$pinocchio" "${only[@]}" >/dev/null
  if [ $build_step = 1 ]; then ninja -C "${dir[$cc]}" -j"$jobs" $targets; fi
done

raw="$build/raw"
rm -rf "$raw"
mkdir -p "$raw"
status=0
mapfile -t entries < "${dir[gcc]}/bench/robots.txt"
for entry in "${entries[@]}"; do
  name="${entry%%=*}"
  for cc in gcc clang; do
    filter=()
    if [ $cc = clang ]; then
      if [ -n "$pinocchio" ]; then filter=("--benchmark_filter=/(gen_|pinocchio)"); else filter=(--benchmark_filter=/gen_); fi
    fi
    echo "== $name ($cc)" >&2
    "${dir[$cc]}/bench/bench_$name" "${filter[@]}" --benchmark_repetitions=$repetitions \
      --benchmark_report_aggregates_only=true --benchmark_min_time=$min_time \
      --benchmark_out="$raw/${cc}_$name.json" --benchmark_out_format=json >"$raw/${cc}_$name.txt" || status=1
    grep '^check ' "$raw/${cc}_$name.txt" | grep -v ' ok ' >&2 || true
  done
done

"${dir[gcc]}/bench/bench_costs" "${entries[@]}" > "$raw/costs.csv"

# Cost of each scene effect (quadruped; a disabled effect must cost nothing): its own table.
echo "== scene effects (gcc)" >&2
"${dir[gcc]}/bench/bench_scene_effects" --benchmark_repetitions=$repetitions --benchmark_report_aggregates_only=true \
  --benchmark_min_time=$min_time > "$raw/scene_effects.txt" || status=1

# Batches (bench_batch: single-state loop vs SIMD vs SIMD + 2 threads, states per second): its own table.
echo "== batches (gcc)" >&2
"${dir[gcc]}/bench/bench_batch" --benchmark_repetitions=$repetitions --benchmark_report_aggregates_only=true \
  --benchmark_min_time=$min_time --benchmark_out="$raw/batch.json" --benchmark_out_format=json > "$raw/batch.txt" || status=1

if [ $callgrind = 1 ]; then
  echo "robot,algo,instructions" > "$raw/callgrind.csv"
  for entry in "${entries[@]}"; do
    name="${entry%%=*}"
    body="$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["context"]["jacobian_body"])' "$raw/gcc_$name.json")"
    out="$raw/callgrind_$name"
    mkdir -p "$out"
    n=32
    valgrind --tool=callgrind --callgrind-out-file="$out/cg.out" "${dir[gcc]}/bench/callgrind_$name" $n "$body" 2>/dev/null
    # each dump: "desc: Trigger: Client Request: <algo>:<count>" ... "totals: <Ir>"
    python3 - "$name" "$n" "$out" >> "$raw/callgrind.csv" <<'PY'
import glob, re, sys
name, n, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
ir = {}
for path in glob.glob(out + "/cg.out*"):
    text = open(path).read()
    m = re.search(r"Client Request: (\w+):(\d+)", text)
    t = re.search(r"^(?:totals|summary): (\d+)", text, re.M)
    if m and t:
        ir[(m.group(1), int(m.group(2)))] = int(t.group(1))
for (algo, count), v in sorted(ir.items()):
    if count == n and (algo, 2 * n) in ir:
        print(f"{name},{algo},{(ir[(algo, 2 * n)] - v) / n:.0f}")
PY
  done
fi

cpu="$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')"
date_iso="$(date -u +%Y-%m-%d)"
{
  echo "cpu=$cpu"
  echo "cores=$(nproc)"
  echo "date=$date_iso $(date -u +%H:%M) UTC"
  echo "gcc=$(g++ --version | head -1)"
  echo "clang=$(clang++ --version | head -1)"
  pin_note=""
  [ -n "$pinocchio" ] && pin_note=", Pinocchio from $(basename "$pinocchio") (header-only, Boost $(dpkg-query -W -f='${Version}' libboost-dev 2>/dev/null))"
  echo "peers=KDL $(dpkg-query -W -f='${Version}' liborocos-kdl-dev 2>/dev/null) (kdl_parser $(dpkg-query -W -f='${Version}' libkdl-parser-dev 2>/dev/null)), MuJoCo $(dpkg-query -W -f='${Version}' libmujoco-dev 2>/dev/null) (Debian packages)$pin_note"
  echo "repetitions=$repetitions"
  echo "min_time=$min_time"
} > "$raw/meta.txt"

if [ $compile_time = 1 ] && [ -f "${dir[gcc]}/bench/instantiate_talos_reduced.cpp" ]; then
  # One compiler process (one core): every function of the talos_reduced header for double.
  for cc in gcc clang; do
    if [ $cc = gcc ]; then cxx=g++; else cxx=clang++; fi
    s=$( { /usr/bin/time -f %e $cxx -std=c++17 -O3 -march=native -DNDEBUG -isystem /usr/include/eigen3 \
             -I"${dir[$cc]}/bench/bench_gen_talos_reduced" -c "${dir[$cc]}/bench/instantiate_talos_reduced.cpp" \
             -o /dev/null; } 2>&1 | tail -1)
    echo "compile_$cc=$s" >> "$raw/meta.txt"
  done
  echo "compile_what=talos_reduced (floating, nv $(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["context"]["nv"])' "$raw/gcc_talos_reduced.json")): every function of the header instantiated for double, -O3 -march=native, one compiler process" >> "$raw/meta.txt"
fi

results="$repo/bench/results"
mkdir -p "$results"
if [ $compile_time = 1 ]; then
  # Header lines, g++ -O2 compile time and memory per robot (bench/results/latest-headers.md).
  specs=("$repo/robots/ur5e.urdf" "$repo/robots/panda_arm.urdf" "$repo/robots/quadruped.urdf:floating"
         "$repo/robots/quadruped.urdf:floating:derivatives" "$repo/robots/humanoid.urdf:floating")
  shared_dir="$repo/../shared/robots"
  if [ -d "$shared_dir" ]; then
    specs+=("$shared_dir/ur5.urdf" "$shared_dir/panda.urdf" "$shared_dir/solo12.urdf:floating"
            "$shared_dir/talos_reduced.urdf:floating" "$shared_dir/talos_reduced.urdf:floating:derivatives"
            "$shared_dir/talos_full_v2.urdf:floating" "$shared_dir/romeo.urdf:floating")
  fi
  "$repo/bench/tools/header_costs.sh" "${dir[gcc]}/generator/rbdgen" "$results/latest-headers.md" "${specs[@]}"
fi
slug="$(echo "$cpu" | tr -c 'A-Za-z0-9\n' '-' | sed 's/--*/-/g; s/-$//')"
pin_md=()
[ -n "$pinocchio" ] && pin_md=(--pinocchio-md "$results/$date_iso-$slug-pinocchio.md")
python3 "$repo/bench/tools/merge_results.py" --raw "$raw" --md "$results/$date_iso-$slug.md" --csv "$results/$date_iso-$slug.csv" \
  "${pin_md[@]}"
cp "$results/$date_iso-$slug.md" "$results/latest.md"
[ -n "$pinocchio" ] && cp "$results/$date_iso-$slug-pinocchio.md" "$results/latest-pinocchio.md"
python3 "$repo/bench/tools/batch_table.py" --json "$raw/batch.json" --text "$raw/batch.txt" --meta "$raw/meta.txt" \
  --md "$results/$date_iso-$slug-batch.md"
cp "$results/$date_iso-$slug-batch.md" "$results/latest-batch.md"
cp "$raw/scene_effects.txt" "$results/$date_iso-$slug-scene-effects.txt"
cp "$raw/scene_effects.txt" "$results/latest-scene-effects.txt"
echo "bench.sh: wrote $results/$date_iso-$slug.md (+ .csv, latest.md)" >&2
exit $status
