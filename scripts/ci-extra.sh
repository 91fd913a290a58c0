#!/usr/bin/env bash
# Extra CI stages (issue 5), each in a build directory of its own:
#   (a) fuzz: clang + libFuzzer + ASan/UBSan, fuzz/fuzz_urdf on URDF -> model -> header for
#       RBDGEN_FUZZ_SECONDS (default 60) from the seed corpus fuzz/corpus; any crash, sanitizer
#       report or leak fails the stage (the input is kept in <prefix>-fuzz/artifacts/);
#   (b) sanitizers: the test suite built with -O1 -fsanitize=address,undefined
#       -fno-omit-frame-pointer -fno-sanitize-recover=all and run with ctest. Subset, for the
#       CI budget: every test except test_generated (26 robots, 10+ min to compile even at -O1);
#       the generated code is still compiled and run under the sanitizers by
#       test_stability_generated (5 hard models) and test_cli.
# Usage: scripts/ci-extra.sh [BUILD_PREFIX] [fuzz|asan|all]   (default: build, all)
# Exit status: non-zero if a stage fails. Prints the wall time of each stage.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
prefix="${1:-$root/build}"
stages="${2:-all}"
jobs="${RBDGEN_JOBS:-$(nproc)}"
fuzz_seconds="${RBDGEN_FUZZ_SECONDS:-60}"
"$root/scripts/install-deps.sh" clang libclang-rt-14-dev

san_flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

stage_fuzz() {
  local dir="$prefix-fuzz"
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link $san_flags" \
    -DRBDGEN_BUILD_FUZZ=ON -DRBDGEN_BUILD_TESTS=OFF
  cmake --build "$dir" --parallel "$jobs" --target fuzz_urdf
  # New inputs go to the first (scratch) directory; the seed corpus in the source tree is read only.
  mkdir -p "$dir/corpus" "$dir/artifacts"
  "$dir/fuzz/fuzz_urdf" -max_total_time="$fuzz_seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
    -print_final_stats=1 -artifact_prefix="$dir/artifacts/" "$dir/corpus" "$root/fuzz/corpus"
}

stage_asan() {
  local dir="$prefix-asan"
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
    -DCMAKE_CXX_FLAGS="$san_flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DRBDGEN_BUILD_TESTS=ON
  # Every test executable except test_generated, plus rbdgen (run by test_cli).
  local targets
  targets=$(cmake --build "$dir" --target help | sed -n 's/^\(test_[A-Za-z0-9_]*\): .*/\1/p' | grep -v '^test_generated$' | sort -u)
  # shellcheck disable=SC2086
  cmake --build "$dir" --parallel "$jobs" --target rbdgen $targets
  ctest --test-dir "$dir" --output-on-failure --parallel "$jobs" --timeout 900 -E '^test_generated_NOT_BUILT|^Generated/'
}

run() {
  local name="$1" start=$SECONDS
  echo "=== ci-extra: $name ==="
  "stage_$name"
  echo "=== ci-extra: $name passed in $((SECONDS - start)) s ==="
}

case "$stages" in
  fuzz) run fuzz ;;
  asan) run asan ;;
  all) run fuzz; run asan ;;
  *) echo "usage: $0 [BUILD_PREFIX] [fuzz|asan|all]" >&2; exit 2 ;;
esac
