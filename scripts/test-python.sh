#!/usr/bin/env bash
# Build the Python package (python/) in a Release build of its own and run its tests (ctest -R
# python_tests: pytest on tests/python). The sanitized build of scripts/test.sh cannot test it: an
# ASan-instrumented extension does not load into an uninstrumented python3 without LD_PRELOAD, so
# that build leaves the package out (RBDGEN_BUILD_PYTHON defaults to OFF with -fsanitize).
# Only the package's target and the rbdgen executable are built (runtime, loader, scene, generator
# library, the extension; the executable for test_cmake_module, which installs this build and makes
# a Python module with generate_robot_dynamics(... PYTHON_MODULE) downstream).
# Usage: scripts/test-python.sh [BUILD_DIR]   (default: build-python)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build-python}"
jobs="${RBDGEN_JOBS:-$(nproc)}"

start=$SECONDS
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRBDGEN_BUILD_TESTS=ON -DRBDGEN_BUILD_PYTHON=ON
cmake --build "$build" --target rbdgen_python rbdgen --parallel "$jobs"
echo "=== test-python: package built in $((SECONDS - start)) s ==="
start=$SECONDS
ctest --test-dir "$build" -R '^python_tests$' --output-on-failure --timeout 600
echo "=== test-python: pytest passed in $((SECONDS - start)) s ==="
