#!/usr/bin/env bash
# Install what is missing, build rbdgen and examples/quickstart for a robot, and run it:
# `rbdgen info` (the tree the loader builds), then the generated dynamics against the runtime
# (max relative errors over 1000 random states, time per call, speed-up). Forward dynamics is
# skipped (with the reason) when the header has none (singular mass matrix) and reported NOT
# VERIFIED when cond(H) eps > 1e-6 on every state; the exit status counts meaningful checks only.
# Usage: scripts/quickstart.sh [ROBOT.urdf] [--floating-base]   (default: robots/ur5e.urdf)
# Environment: RBDGEN_BUILD_DIR (default: build), RBDGEN_JOBS (default: nproc).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${RBDGEN_BUILD_DIR:-$root/build}"
robot="$root/robots/ur5e.urdf"
floating=OFF
info_flags=()
for arg in "$@"; do
  case "$arg" in
    --floating-base) floating=ON; info_flags+=(--floating-base) ;;
    -h|--help) sed -n '2,8p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "quickstart.sh: unknown option '$arg' (see --help)" >&2; exit 2 ;;
    *) robot="$arg" ;;
  esac
done
[ -f "$robot" ] || { echo "quickstart.sh: $robot: no such file" >&2; exit 2; }
robot="$(cd "$(dirname "$robot")" && pwd)/$(basename "$robot")"

"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      "-DRBDGEN_QUICKSTART_URDF=$robot" "-DRBDGEN_QUICKSTART_FLOATING=$floating" >/dev/null
cmake --build "$build" --parallel "${RBDGEN_JOBS:-$(nproc)}" --target rbdgen quickstart
echo
"$build/generator/rbdgen" info "$robot" "${info_flags[@]}"
echo
"$build/examples/quickstart/quickstart"
