#!/usr/bin/env bash
# Install what is missing, build everything and run every test (ctest) under AddressSanitizer +
# UndefinedBehaviorSanitizer, then fuzz the URDF pipeline (scripts/fuzz.sh). Exit status = pass/fail.
#
# One build serves the whole suite: g++ -O1 -g1 -fsanitize=address,undefined, warnings as errors
# (the project's and the generated headers' -Wall -Wextra -Wpedantic -Wshadow -Werror). A plain
# Release build and a second, instrumented one of the same suite do not fit CI's 30 minutes on two
# cores; the instrumented build checks strictly more. -Wno-maybe-uninitialized: with the sanitizers'
# instrumentation g++ 12 reports it inside Eigen's assignment loops (false positives). The adapters
# of generated headers and the quick test sources (whose run time is negligible) compile at -O0
# (RBDGEN_GENERATED_TEST_OPTIONS, RBDGEN_QUICK_TEST_OPTIONS; see tests/CMakeLists.txt). The adapters
# compile the generated headers without the sanitizers and without debug information, with
# libstdc++'s bounds assertions (-D_GLIBCXX_ASSERTIONS) and Eigen's (no NDEBUG here) on: generated
# code is straight-line arithmetic on fixed-size Eigen objects and std::arrays indexed by constants,
# where an out-of-range index is what could go wrong and the assertions catch it; ASan + UBSan
# doubled each adapter's compile time (quadruped: 82 s vs 31 s; an xsimd batch adapter ran > 20 min)
# and took CI past its limit. Everything else (runtime, loader, generator, scenes, every test
# harness calling the adapters) stays instrumented. -DEIGEN_MALLOC_ALREADY_ALIGNED=0: Eigen picks its
# aligned allocator by __SANITIZE_ADDRESS__ (handmade under ASan, malloc otherwise); the adapters
# must pick the instrumented code's, or a matrix allocated on one side and freed on the other breaks.
# The Release -O3 -march=native builds are exercised by scripts/quickstart.sh and scripts/bench.sh
# (whose build runs the same agreement checks: ctest -R bench_agreement).
# Then scripts/test-python.sh builds the Python package in BUILD_DIR-python (Release: an ASan
# extension cannot be loaded into python3) and runs its pytest suite.
# Usage: scripts/test.sh [BUILD_DIR]   (default: build-test; the fuzzer uses BUILD_DIR-fuzz)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build-test}"
"$root/scripts/install-deps.sh"
jobs="${RBDGEN_JOBS:-$(nproc)}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
san_flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"

start=$SECONDS
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DCMAKE_CXX_FLAGS="$san_flags -Wno-maybe-uninitialized" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DRBDGEN_BUILD_TESTS=ON -DRBDGEN_WERROR=ON -DRBDGEN_QUICK_TEST_OPTIONS=-O0 \
  "-DRBDGEN_GENERATED_TEST_OPTIONS=-O0;-g0;-fno-sanitize=all;-D_GLIBCXX_ASSERTIONS;-DEIGEN_MALLOC_ALREADY_ALIGNED=0"
cmake --build "$build" --parallel "$jobs"
echo "=== test: build done in $((SECONDS - start)) s ==="

start=$SECONDS
ctest --test-dir "$build" --output-on-failure --parallel "$jobs" --timeout 900
echo "=== test: every test passed under ASan + UBSan in $((SECONDS - start)) s ==="

# The Python package, which an ASan build cannot load into python3: a Release build of its own.
# (its downstream PYTHON_MODULE test takes rbdgen and its executable from this build's install)
RBDGEN_TEST_GENERATOR_BUILD="$build" "$root/scripts/test-python.sh" "$build-python"

"$root/scripts/fuzz.sh" "$build-fuzz"
