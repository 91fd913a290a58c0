#!/usr/bin/env bash
# Install what is missing, build, and run rbdgen on a bundled robot.
# Usage: scripts/quickstart.sh [ROBOT.urdf]   (default: robots/ur5e.urdf)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
robot="${1:-$root/robots/ur5e.urdf}"
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --parallel "${RBDGEN_JOBS:-$(nproc)}" --target rbdgen
"$build/generator/rbdgen" info "$robot"
