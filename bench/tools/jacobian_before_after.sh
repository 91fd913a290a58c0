#!/usr/bin/env bash
# The Jacobian of one link from q, before and after it walked only the link's support path (issue
# 14's goal: >= 3x on solo12 and talos_reduced with a free base), measured in one binary: headers of
# the generator at commit 622c618 (before that work: jacobian(body, q) computed the kinematics of
# every link, then the link's Jacobian) and of this checkout's rbdgen, the same states, agreement
# checked first (jacobian_path/main.cpp). Needs ../shared/robots, git history, cmake, ninja.
#   bench/tools/jacobian_before_after.sh RBDGEN OUT.md [CXX]
# (RBDGEN_BEFORE=path: an rbdgen already built at that commit, instead of building one.)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
rbdgen="$(realpath "$1")"
out="$2"
cxx="${3:-g++}"
before_commit=622c618
shared="$root/../shared/robots"
robots=("solo12:HR_LOWER_LEG,HR_FOOT" "talos_reduced:leg_right_6_link,right_sole_link")
if [ ! -d "$shared" ]; then
  echo "jacobian_before_after: needs the real robots in $shared (solo12, talos_reduced)" >&2
  exit 2
fi
work="$(mktemp -d)"
cleanup() {
  git -C "$root" worktree remove --force "$work/src" > /dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT

if [ -n "${RBDGEN_BEFORE:-}" ]; then
  before="$(realpath "$RBDGEN_BEFORE")" # an rbdgen built at $before_commit already
else
  echo "jacobian_before_after: building rbdgen at $before_commit" >&2
  git -C "$root" worktree add --detach "$work/src" "$before_commit" > /dev/null 2>&1
  cmake -S "$work/src" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
  cmake --build "$work/build" --target rbdgen > /dev/null
  before="$work/build/generator/rbdgen"
fi

flags=(-std=c++17 -O3 -march=native -DNDEBUG -isystem /usr/include/eigen3 -I"$work/gen" -I"$root/bench/tools/jacobian_path")
objects=()
for spec in "${robots[@]}"; do
  robot="${spec%%:*}"
  for version in before after; do
    gen="$rbdgen"
    [ "$version" = before ] && gen="$before"
    "$gen" generate "$shared/$robot.urdf" --floating-base --namespace "${robot}_$version" --out "$work/gen" > /dev/null 2> "$work/warnings" \
      || { cat "$work/warnings" >&2; exit 1; }
    echo "jacobian_before_after: compiling ${robot}_$version ($(wc -l < "$work/gen/${robot}_$version/dynamics.hpp") lines)" >&2
    "$cxx" "${flags[@]}" -DRBDGEN_NS="${robot}_$version" -DRBDGEN_ROBOT="\"$robot\"" -DRBDGEN_VERSION_TAG="\"$version\"" \
      -c "$root/bench/tools/jacobian_path/Wrapper.cpp" -o "$work/${robot}_$version.o"
    objects+=("$work/${robot}_$version.o")
  done
done
"$cxx" "${flags[@]}" "$root/bench/tools/jacobian_path/main.cpp" "${objects[@]}" -o "$work/jacobian_path"
{
  echo "# jacobian(body, q) before and after the support-path walk"
  echo
  echo "$(date -u +%F), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $("$cxx" --version | head -1), -O3 -march=native."
  echo "Before: headers of rbdgen at commit $before_commit (the kinematics of every link, then the link's Jacobian);"
  echo "after: this checkout's. Both with a free base, in one binary, on the same 1,024 states (cycled),"
  echo "each call not inlined and its 6 x nv result read; median of 9 alternating runs of 200,000 calls."
  echo
  "$work/jacobian_path" "${robots[@]}"
} > "$work/table.md"
mv "$work/table.md" "$out"
cat "$out"
