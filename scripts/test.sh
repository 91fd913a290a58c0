#!/usr/bin/env bash
# Install what is missing, build everything, run every test (ctest), then the same suite under
# ASan + UBSan and the URDF fuzzer (scripts/ci-extra.sh). Exit status = pass/fail.
# Usage: scripts/test.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
"$root/scripts/install-deps.sh"
jobs="${RBDGEN_JOBS:-$(nproc)}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRBDGEN_BUILD_TESTS=ON
cmake --build "$build" --parallel "$jobs"
ctest --test-dir "$build" --output-on-failure --parallel "$jobs" --timeout 900
# Then the sanitizer build (ASan + UBSan) of the test suite and the URDF fuzzer (>= 60 s).
"$root/scripts/ci-extra.sh" "$build"
