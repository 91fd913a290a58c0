#!/usr/bin/env bash
# Build the Python package (python/) in a Release build of its own and run its tests (ctest -R
# python_tests: pytest on tests/python). The sanitized build of scripts/test.sh cannot test it: an
# ASan-instrumented extension does not load into an uninstrumented python3 without LD_PRELOAD, so
# that build leaves the package out (RBDGEN_BUILD_PYTHON defaults to OFF with -fsanitize).
# Only the package's target is built (runtime, loader, scene, generator library, the extension).
# tests/python/test_cmake_module.py makes a Python module with generate_robot_dynamics(...
# PYTHON_MODULE) in a downstream project, against a prefix holding rbdgen (with its rbdgen
# executable) and this build's package: rbdgen is installed from RBDGEN_TEST_GENERATOR_BUILD when
# set (scripts/test.sh: its sanitized build, whose executable is built anyway), else from this
# build, which then also builds the executable (a few minutes more).
# Usage: scripts/test-python.sh [BUILD_DIR]   (default: build-python)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build-python}"
jobs="${RBDGEN_JOBS:-$(nproc)}"

start=$SECONDS
# Under scripts/test.sh (CI) only results are checked, not speed: the package at -O1 and the modules
# the tests compile (rbdgen.compile, PYTHON_MODULE) at -O0 build in a fraction of the time.
release_flags=()
if [[ -n "${RBDGEN_TEST_GENERATOR_BUILD:-}" ]]; then
  release_flags=(-DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG")
  export RBDGEN_COMPILE_OPT="${RBDGEN_COMPILE_OPT:--O0}"
fi
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRBDGEN_BUILD_TESTS=ON -DRBDGEN_BUILD_PYTHON=ON \
  "${release_flags[@]}"
targets=(rbdgen_python)
if [[ -z "${RBDGEN_TEST_GENERATOR_BUILD:-}" ]]; then
  targets+=(rbdgen)
fi
cmake --build "$build" --target "${targets[@]}" --parallel "$jobs"
echo "=== test-python: package built in $((SECONDS - start)) s ==="
start=$SECONDS
ctest --test-dir "$build" -R '^python_tests$' --output-on-failure --timeout 600
echo "=== test-python: pytest passed in $((SECONDS - start)) s ==="
