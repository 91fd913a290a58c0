#!/usr/bin/env bash
# Size and compile cost of every generated bench header: lines, and for one translation unit that
# instantiates every function for double (bench/tools/instantiate_all.cpp.in) with g++ -O2 (what
# a user's build does), the wall time and peak memory of the compiler (one process, one core).
#   bench/tools/header_costs.sh BENCH_BUILD_DIR OUT.md [robot...]
# Called by scripts/bench.sh (its g++ build); runs alone on any configured bench build.
set -euo pipefail
build="$1"
out="$2"
shift 2
robots=("$@")
if [ ${#robots[@]} -eq 0 ]; then
  for f in "$build"/bench/instantiate_*.cpp; do
    r="$(basename "$f" .cpp)"
    robots+=("${r#instantiate_}")
  done
fi
tmp="$(mktemp)"
trap 'rm -f "$tmp"' EXIT
{
  echo "# Generated headers: lines and compile cost"
  echo
  echo "$(date -u +%F), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(g++ --version | head -1)."
  echo "One g++ -O2 process per robot compiling every function of the header for double"
  echo "(bench/tools/instantiate_all.cpp.in); wall time and the compiler's peak resident memory."
  echo
  echo "| robot | nv | header lines | compile s | peak MB |"
  echo "|---|--:|--:|--:|--:|"
} > "$tmp"
for r in "${robots[@]}"; do
  src="$build/bench/instantiate_$r.cpp"
  header="$(ls "$build"/bench/bench_gen_"$r"/*/dynamics.hpp 2>/dev/null | head -1)"
  [ -f "$src" ] && [ -n "$header" ] || { echo "header_costs: no header for $r in $build" >&2; exit 1; }
  lines=$(wc -l < "$header")
  nv=$(grep -m1 -o 'nv = [0-9]*' "$header" | grep -o '[0-9]*$')
  read -r secs kb < <({ /usr/bin/time -f "%e %M" g++ -std=c++17 -O2 -DNDEBUG -isystem /usr/include/eigen3 \
                          -I"$(dirname "$(dirname "$header")")" -c "$src" -o /dev/null; } 2>&1 | tail -1)
  echo "| $r | $nv | $lines | $secs | $((kb / 1024)) |" >> "$tmp"
  echo "header_costs: $r: $lines lines, $secs s, $((kb / 1024)) MB" >&2
done
mv "$tmp" "$out"
trap - EXIT
