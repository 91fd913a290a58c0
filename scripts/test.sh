#!/usr/bin/env bash
# Install what is missing, build everything and run every test (ctest) under AddressSanitizer +
# UndefinedBehaviorSanitizer, then fuzz the URDF pipeline (scripts/fuzz.sh). Exit status = pass/fail.
#
# One build serves the whole suite: clang++ -O1 -g1 -fsanitize=address,undefined, warnings as errors
# (the project's and the generated headers' -Wall -Wextra -Wpedantic -Wshadow -Werror). clang++ rather
# than g++ for this build because it compiles the suite about 2.5x faster at the same flags
# (measured: talos_reduced adapter 22 s vs 62 s, singular-pose tests 27 s vs 81 s, SceneDynamics.cpp
# 48 s vs 82 s): with g++ the build alone took 34 of CI's 45 minutes on two cores. g++ still builds
# and checks: scripts/test-python.sh builds the package, the ur5e derivatives header instantiated
# for double and float, the quick start and the scene example with g++ -Werror (generated headers
# under -Wall -Wextra -Wpedantic -Wshadow -Werror) and runs their tests. The adapters of generated
# headers and the quick test sources (whose run time is negligible) compile at -O0
# (RBDGEN_GENERATED_TEST_OPTIONS, RBDGEN_QUICK_TEST_OPTIONS; see tests/CMakeLists.txt). The adapters
# compile the generated headers without the sanitizers and without debug information, with
# libstdc++'s bounds assertions (-D_GLIBCXX_ASSERTIONS) and Eigen's (no NDEBUG here) on: generated
# code is straight-line arithmetic on fixed-size Eigen objects and std::arrays indexed by constants,
# where an out-of-range index is what could go wrong and the assertions catch it; ASan + UBSan
# doubled each adapter's compile time and an xsimd batch adapter ran > 20 min under g++. Everything
# else (runtime, loader, generator, scenes, every test harness calling the adapters) stays
# instrumented. -DEIGEN_MALLOC_ALREADY_ALIGNED=0 for every translation unit: Eigen picks its heap
# allocator by __SANITIZE_ADDRESS__ (handmade aligned under g++'s ASan, plain malloc otherwise;
# clang 14 does not define it), and a matrix allocated by one and freed by the other is an invalid
# free: the instrumented and uninstrumented code must agree, whatever the compiler.
# RBDGEN_CTEST_PER_CASE=OFF: one ctest test per GoogleTest executable (each sanitized process costs
# ~0.3 s to start; per case that was a third of the suite's run time).
# The Release -O3 -march=native builds are exercised by scripts/quickstart.sh and scripts/bench.sh
# (whose build runs the same agreement checks: ctest -R bench_agreement).
# Then scripts/test-python.sh builds the Python package in BUILD_DIR-python (Release, g++: an ASan
# extension cannot be loaded into python3) and runs its pytest suite.
# Usage: scripts/test.sh [BUILD_DIR]   (default: build-test; the fuzzer uses BUILD_DIR-fuzz)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build-test}"
"$root/scripts/install-deps.sh" clang libclang-rt-14-dev
jobs="${RBDGEN_JOBS:-$(nproc)}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
san_flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"

start=$SECONDS
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
  -DCMAKE_CXX_FLAGS="$san_flags -DEIGEN_MALLOC_ALREADY_ALIGNED=0" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DRBDGEN_BUILD_TESTS=ON -DRBDGEN_WERROR=ON -DRBDGEN_CTEST_PER_CASE=OFF -DRBDGEN_QUICK_TEST_OPTIONS=-O0 \
  "-DRBDGEN_GENERATED_TEST_OPTIONS=-O0;-g0;-fno-sanitize=all;-D_GLIBCXX_ASSERTIONS"
cmake --build "$build" --parallel "$jobs"
echo "=== test: build done in $((SECONDS - start)) s ==="

start=$SECONDS
ctest --test-dir "$build" --output-on-failure --parallel "$jobs" --timeout 900
echo "=== test: every test passed under ASan + UBSan in $((SECONDS - start)) s ==="

# The Python package, which an ASan build cannot load into python3: a Release build of its own.
# (its downstream PYTHON_MODULE test takes rbdgen and its executable from this build's install)
RBDGEN_TEST_GENERATOR_BUILD="$build" "$root/scripts/test-python.sh" "$build-python"

"$root/scripts/fuzz.sh" "$build-fuzz"
