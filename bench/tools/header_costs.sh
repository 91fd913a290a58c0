#!/usr/bin/env bash
# Size and compile cost of generated headers: for each robot, `rbdgen generate --instantiate` (+
# --derivatives when asked), the header's lines, and g++ -O2 compiling dynamics_double.cpp (every
# function of the header instantiated for double: what a user's build pays once per scalar) in one
# process: its CPU time (user + system: steady on a shared machine) and peak memory.
#   bench/tools/header_costs.sh RBDGEN OUT.md ROBOT.urdf[:floating][:derivatives] ...
# Called by scripts/bench.sh; runs alone too (nothing else needed but rbdgen and g++).
set -euo pipefail
rbdgen="$1"
out="$2"
shift 2
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
table="$work/table.md"
{
  echo "# Generated headers: lines and compile cost"
  echo
  echo "$(date -u +%F), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(g++ --version | head -1)."
  echo "Per robot: the header's lines, and one g++ -O2 process compiling every function of it for double"
  echo "(\`rbdgen generate --instantiate\`'s dynamics_double.cpp): CPU time (user + system), peak resident memory."
  echo
  echo "| robot | options | nv | header lines | compile CPU s | peak MB |"
  echo "|---|---|--:|--:|--:|--:|"
} > "$table"
for spec in "$@"; do
  IFS=: read -r urdf opt1 opt2 <<< "$spec"
  name="$(basename "$urdf" .urdf)"
  args=(--instantiate)
  label="fixed base"
  for o in $opt1 $opt2; do
    case "$o" in
      floating) args+=(--floating-base); label="floating base" ;;
      derivatives) args+=(--derivatives); label="$label, derivatives" ;;
      *) echo "header_costs: unknown option '$o' in $spec" >&2; exit 2 ;;
    esac
  done
  "$rbdgen" generate "$urdf" --out "$work/$name" --namespace robot "${args[@]}" > /dev/null 2> "$work/warnings"
  header="$work/$name/robot/dynamics.hpp"
  lines=$(wc -l < "$header")
  nv=$(grep -o 'constexpr int nv = [0-9]*' "$header" | tail -1 | grep -o '[0-9]*$')
  read -r user sys kb < <({ /usr/bin/time -f "%U %S %M" g++ -std=c++17 -O2 -DNDEBUG -isystem /usr/include/eigen3 \
                          -I"$work/$name" -c "$work/$name/robot/dynamics_double.cpp" -o /dev/null; } 2>&1 | tail -1)
  secs=$(python3 -c "print(f'{$user + $sys:.1f}')")
  echo "| $name | $label | $nv | $lines | $secs | $((kb / 1024)) |" >> "$table"
  echo "header_costs: $name ($label): $lines lines, $secs s, $((kb / 1024)) MB" >&2
done
mv "$table" "$out"
