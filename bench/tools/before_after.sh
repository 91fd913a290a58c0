#!/usr/bin/env bash
# The generated functions of two generators side by side, in one binary: headers of an rbdgen built
# at an earlier commit (before) and of this checkout's (after), the same states, agreement checked
# first (to 1e-12 relative), then 9 alternating timed runs of each (before_after/main.cpp).
# Needs ../shared/robots, git history, cmake, ninja.
#   bench/tools/before_after.sh RBDGEN OUT.md [CXX]
# Environment:
#   BEFORE=<commit>        the before generator's commit (default: HEAD, i.e. this checkout's last commit)
#   RBDGEN_BEFORE=path     an rbdgen built at that commit already (else one is built in a worktree)
#   ROBOTS="robot[+free][:link,...] ..."   default: ur5, solo12 and talos_reduced with a free base
#   FUNCTIONS="name;name..."               default: every function of before_after/Wrapper.cpp
#   TITLE="..."                            the table's heading
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
rbdgen="$(realpath "$1")"
out="$2"
cxx="${3:-g++}"
before_commit="${BEFORE:-HEAD}"
robots=(${ROBOTS:-ur5:wrist_3_link,tool0 solo12+free:HR_LOWER_LEG,HR_FOOT talos_reduced+free:leg_right_6_link,right_sole_link})
shared="$root/../shared/robots"
if [ ! -d "$shared" ]; then
  echo "before_after: needs the real robots in $shared" >&2
  exit 2
fi
work="$(mktemp -d)"
cleanup() {
  git -C "$root" worktree remove --force "$work/src" > /dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT

if [ -n "${RBDGEN_BEFORE:-}" ]; then
  before="$(realpath "$RBDGEN_BEFORE")"
else
  echo "before_after: building rbdgen at $before_commit" >&2
  git -C "$root" worktree add --detach "$work/src" "$before_commit" > /dev/null 2>&1
  cmake -S "$work/src" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRBDGEN_BUILD_TESTS=OFF > /dev/null
  cmake --build "$work/build" --target rbdgen > /dev/null
  before="$work/build/generator/rbdgen"
fi

flags=(-std=c++17 -O3 -march=native -DNDEBUG -isystem /usr/include/eigen3 -I"$work/gen" -I"$root/bench/tools/before_after")
objects=()
specs=()
for spec in "${robots[@]}"; do
  name="${spec%%:*}"
  links=""
  [ "$name" != "$spec" ] && links=":${spec#*:}"
  robot="${name%+free}"
  options=()
  [ "$robot" != "$name" ] && options=(--floating-base)
  specs+=("$robot$links")
  for version in before after; do
    gen="$rbdgen"
    [ "$version" = before ] && gen="$before"
    "$gen" generate "$shared/$robot.urdf" "${options[@]}" --namespace "${robot}_$version" --out "$work/gen" > /dev/null 2> "$work/warnings" \
      || { cat "$work/warnings" >&2; exit 1; }
    echo "before_after: compiling ${robot}_$version ($(wc -l < "$work/gen/${robot}_$version/dynamics.hpp") lines)" >&2
    "$cxx" "${flags[@]}" -DRBDGEN_NS="${robot}_$version" -DRBDGEN_ROBOT="\"$robot\"" -DRBDGEN_VERSION_TAG="\"$version\"" \
      -c "$root/bench/tools/before_after/Wrapper.cpp" -o "$work/${robot}_$version.o"
    objects+=("$work/${robot}_$version.o")
  done
done
"$cxx" "${flags[@]}" "$root/bench/tools/before_after/main.cpp" "${objects[@]}" -o "$work/before_after"
args=()
[ -n "${FUNCTIONS:-}" ] && args=(--functions "$FUNCTIONS")
{
  echo "# ${TITLE:-Generated functions before and after}"
  echo
  echo "$(date -u +%F), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $("$cxx" --version | head -1), -O3 -march=native."
  echo "Before: headers of rbdgen at commit $(git -C "$root" rev-parse --short "$before_commit"); after: this checkout's ($(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet || echo ' + changes'))."
  echo "In one binary, on the same 256 states (cycled), each call not inlined and its result read; median"
  echo "of 9 alternating runs of about 20 ms each. Robots from ../shared/robots (+free: with a free base)."
  echo
  "$work/before_after" "${args[@]}" "${specs[@]}"
} > "$work/table.md"
mv "$work/table.md" "$out"
cat "$out"
