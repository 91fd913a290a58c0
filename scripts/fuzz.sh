#!/usr/bin/env bash
# Fuzz URDF text -> loader -> model -> emitted header (fuzz/fuzz_urdf, libFuzzer) for
# RBDGEN_FUZZ_SECONDS (default 60) from the seed corpus fuzz/corpus. libFuzzer needs clang, so this
# is its own build directory: clang++ -O1 -g with -fsanitize=fuzzer-no-link,address,undefined, only
# the libraries the target needs (the runtime and scene libraries, which only models the loader
# accepted reach, without UBSan: see fuzz/CMakeLists.txt). Any crash, sanitizer report, leak or undocumented exception fails
# (the input is kept in BUILD_DIR/artifacts/ and belongs in tests/cli/bad and fuzz/corpus).
# Usage: scripts/fuzz.sh [BUILD_DIR]   (default: build-fuzz). Called by scripts/test.sh.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir="${1:-$root/build-fuzz}"
jobs="${RBDGEN_JOBS:-$(nproc)}"
fuzz_seconds="${RBDGEN_FUZZ_SECONDS:-60}"
"$root/scripts/install-deps.sh" clang libclang-rt-14-dev

san_flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

start=$SECONDS
# Warnings are checked by the g++ build of scripts/test.sh (-Werror there).
cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link $san_flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DRBDGEN_BUILD_FUZZ=ON -DRBDGEN_BUILD_TESTS=OFF \
  -DRBDGEN_WERROR=OFF >/dev/null
cmake --build "$dir" --parallel "$jobs" --target fuzz_urdf
echo "=== fuzz: build done in $((SECONDS - start)) s ==="

start=$SECONDS
# New inputs go to the first (scratch) directory; the seed corpus in the source tree is read only.
mkdir -p "$dir/corpus" "$dir/artifacts"
"$dir/fuzz/fuzz_urdf" -max_total_time="$fuzz_seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
  -print_final_stats=1 -artifact_prefix="$dir/artifacts/" "$dir/corpus" "$root/fuzz/corpus"
echo "=== fuzz: ${fuzz_seconds} s passed in $((SECONDS - start)) s ==="
