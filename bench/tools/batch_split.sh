#!/usr/bin/env bash
# Where the batch functions' time goes (bench/tools/batch_split.cpp): per robot and scalar, the
# single-state and SIMD forward kinematics and mass matrix computed only, then with their outputs
# written as bench_batch writes them, and the bare writing of those bytes; markdown on stdout.
#
#   bench/tools/batch_split.sh [--rbdgen PATH] [--cxx COMPILER] [URDF[:free] ...]
#
# Default robots: robots/ur5e.urdf and, when ../shared exists, its talos_reduced.urdf with a free
# base; default rbdgen: build/generator/rbdgen; default compiler: g++ (-O3 -march=native, as
# bench_batch). Needs libeigen3-dev and libxsimd-dev.
set -euo pipefail
repo="$(cd "$(dirname "$0")/../.." && pwd)"
rbdgen="$repo/build/generator/rbdgen"
cxx=g++
robots=()
while [ $# -gt 0 ]; do
  case "$1" in
    --rbdgen) rbdgen="$2"; shift ;;
    --cxx) cxx="$2"; shift ;;
    -h|--help) sed -n 2,10p "$0"; exit 0 ;;
    -*) echo "batch_split.sh: unknown option '$1'" >&2; exit 2 ;;
    *) robots+=("$1") ;;
  esac
  shift
done
if [ ${#robots[@]} -eq 0 ]; then
  robots=("$repo/robots/ur5e.urdf")
  [ -f "$repo/../shared/robots/talos_reduced.urdf" ] && robots+=("$repo/../shared/robots/talos_reduced.urdf:free")
fi
[ -x "$rbdgen" ] || { echo "batch_split.sh: no rbdgen at $rbdgen (build it, or give --rbdgen)" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "# Batch forward kinematics and mass matrix: computing against writing — $(date -u '+%Y-%m-%d %H:%M UTC')"
echo
echo "- CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
echo "- Compiler: $($cxx --version | head -1), \`-O3 -march=native\`; bench/tools/batch_split.cpp, ns a state, medians of 9 runs of 2,000 calls"
for spec in "${robots[@]}"; do
  urdf="${spec%:free}"
  free=()
  [ "$spec" != "$urdf" ] && free=(--floating-base)
  name="$(basename "$urdf" .urdf)"
  "$rbdgen" generate "$urdf" "${free[@]}" --batch --namespace "$name" --out "$work/$name" > /dev/null
  for scalar in double float; do
    "$cxx" -std=c++17 -O3 -march=native -DNDEBUG -isystem /usr/include/eigen3 -include "$work/$name/$name/batch.hpp" \
      -DNS="$name" -DSCALAR="$scalar" "$repo/bench/tools/batch_split.cpp" -o "$work/split_${name}_$scalar" -lpthread
    echo
    echo "## $name${free:+ + free base}, $scalar"
    echo
    "$work/split_${name}_$scalar"
  done
done
