#!/usr/bin/env bash
# Extra CI stages (issue 5), in one build directory (<prefix>-san) compiled by clang++ with
#   -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fsanitize=fuzzer-no-link
# so that one instrumented build serves both stages:
#   (a) sanitizers: tests under AddressSanitizer + UndefinedBehaviorSanitizer (ctest). A subset, for
#       the CI budget (30 min on 2 cores; the Release build and all tests take ~18): the executables
#       that drive the whole pipeline -- loader (test_loader), generator and CLI (test_cli: generation,
#       the broken-URDF corpus; test_codegen, test_scene_emit), scenes and
#       simulation on the runtime algorithms (test_scene: FK, FV, RNEA, CRBA, Jacobians, CoM,
#       integrators; test_simulate_cli). The runtime's own unit tests (sva, dynamics, kinematics,
#       stability: ~1,100 core-seconds to compile instrumented) and the tests compiling generated
#       headers run in the Release build only. Warnings are checked by the main (g++, -Werror) build;
#       clang's -Wpedantic flags GoogleTest's typed-test macros, so no -Werror here;
#   (b) fuzz: fuzz/fuzz_urdf (libFuzzer) on URDF -> model -> header for RBDGEN_FUZZ_SECONDS (default
#       60) from the seed corpus fuzz/corpus; any crash, sanitizer report or leak fails the stage (the
#       input is kept in <prefix>-san/artifacts/ and belongs in tests/cli/bad afterwards).
# Usage: scripts/ci-extra.sh [BUILD_PREFIX]   (default: build). Prints the wall time of each stage.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
prefix="${1:-$root/build}"
jobs="${RBDGEN_JOBS:-$(nproc)}"
fuzz_seconds="${RBDGEN_FUZZ_SECONDS:-60}"
"$root/scripts/install-deps.sh" clang libclang-rt-14-dev

san_flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
dir="$prefix-san"

start=$SECONDS
echo "=== ci-extra: sanitizer build ==="
cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link $san_flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DRBDGEN_BUILD_FUZZ=ON -DRBDGEN_BUILD_TESTS=ON \
  -DRBDGEN_WERROR=OFF
targets=(test_loader test_cli test_codegen test_scene_emit test_scene test_simulate_cli)
cmake --build "$dir" --parallel "$jobs" --target rbdgen fuzz_urdf "${targets[@]}"
echo "=== ci-extra: sanitizer build done in $((SECONDS - start)) s ==="

start=$SECONDS
echo "=== ci-extra: test suite under ASan + UBSan ==="
# Tests of the executables above (the others are registered but not built: *_NOT_BUILT). In a
# reused build directory, forget the tests of executables that are not in the list (stale binaries).
while IFS= read -r f; do
  t="$(basename "$f")"; t="${t%%\[1\]_tests.cmake}"
  [[ " ${targets[*]} " == *" $t "* ]] || rm -f "$f"
done < <(find "$dir/tests" -name '*\[1\]_tests.cmake')
ctest --test-dir "$dir" --output-on-failure --parallel "$jobs" --timeout 900 -E '_NOT_BUILT|^install\.'
echo "=== ci-extra: sanitizers passed in $((SECONDS - start)) s ==="

start=$SECONDS
echo "=== ci-extra: fuzz ${fuzz_seconds} s ==="
# New inputs go to the first (scratch) directory; the seed corpus in the source tree is read only.
mkdir -p "$dir/corpus" "$dir/artifacts"
"$dir/fuzz/fuzz_urdf" -max_total_time="$fuzz_seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
  -print_final_stats=1 -artifact_prefix="$dir/artifacts/" "$dir/corpus" "$root/fuzz/corpus"
echo "=== ci-extra: fuzz passed in $((SECONDS - start)) s ==="
