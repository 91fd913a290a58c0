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
#   DERIVATIVES=1                          headers generated with --derivatives, whose two functions
#                                          are timed too
#   LAYOUTS=n                              link the objects at n code layouts (n > 1: runs of padding
#                                          between them, a binary each; the table gives the median of
#                                          the layouts' medians and their range): the same machine
#                                          code at another address ran up to 1.5x slower or faster
#                                          (large straight-line bodies: instruction fetch, 4K aliasing)
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
  [ "${DERIVATIVES:-0}" = 1 ] && options+=(--derivatives)
  specs+=("$robot$links")
  for version in before after; do
    gen="$rbdgen"
    [ "$version" = before ] && gen="$before"
    "$gen" generate "$shared/$robot.urdf" "${options[@]}" --namespace "${robot}_$version" --out "$work/gen" > /dev/null 2> "$work/warnings" \
      || { cat "$work/warnings" >&2; exit 1; }
    echo "before_after: compiling ${robot}_$version ($(wc -l < "$work/gen/${robot}_$version/dynamics.hpp") lines)" >&2
    defines=()
    [ "${DERIVATIVES:-0}" = 1 ] && defines=(-DRBDGEN_DERIVATIVES)
    "$cxx" "${flags[@]}" "${defines[@]}" -DRBDGEN_NS="${robot}_$version" -DRBDGEN_ROBOT="\"$robot\"" \
      -DRBDGEN_VERSION_TAG="\"$version\"" -c "$root/bench/tools/before_after/Wrapper.cpp" -o "$work/${robot}_$version.o"
    objects+=("$work/${robot}_$version.o")
  done
done
"$cxx" "${flags[@]}" -c "$root/bench/tools/before_after/main.cpp" -o "$work/main.o"
args=()
[ -n "${FUNCTIONS:-}" ] && args=(--functions "$FUNCTIONS")
layouts="${LAYOUTS:-1}"
# Layout l: before object k, a run of (l + k) x 1216 mod 4096 bytes of padding code (never called):
# every function of every object starts at another address modulo 4 KiB in each layout.
run_layouts() {
  for ((l = 0; l < layouts; ++l)); do
    linked=()
    for ((k = 0; k < ${#objects[@]}; ++k)); do
      bytes=$(( ((l + k) * 1216) % 4096 + 64 ))
      printf '.section .text.rbdgen_pad\n.globl rbdgen_pad_%d_%d\nrbdgen_pad_%d_%d:\n.skip %d, 0x90\nret\n.section .note.GNU-stack,"",@progbits\n' \
        "$l" "$k" "$l" "$k" "$bytes" > "$work/pad_${l}_$k.s"
      "$cxx" -c "$work/pad_${l}_$k.s" -o "$work/pad_${l}_$k.o"
      linked+=("$work/pad_${l}_$k.o" "${objects[$k]}")
    done
    "$cxx" "$work/main.o" "${linked[@]}" -o "$work/before_after_$l"
    "$work/before_after_$l" --raw "${args[@]}" "${specs[@]}" || return 1
  done
}
{
  echo "# ${TITLE:-Generated functions before and after}"
  echo
  echo "$(date -u +%F), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $("$cxx" --version | head -1), -O3 -march=native."
  echo "Before: headers of rbdgen at commit $(git -C "$root" rev-parse --short "$before_commit"); after: this checkout's ($(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet || echo ' + changes'))."
  echo "In one binary, on the same 256 states (cycled), each call not inlined and its result read; median"
  echo "of 9 alternating runs of about 20 ms each. Robots from ../shared/robots (+free: with a free base)."
  [ "$layouts" -gt 1 ] && echo "Each binary linked at $layouts code layouts: the median of the layouts' medians [their range]."
  echo
  run_layouts | python3 -c '
import sys, statistics, collections
rows = collections.OrderedDict()
for line in sys.stdin:
    robot, function, link, before, after, diff = line.rstrip("\n").split("\t")
    r = rows.setdefault((robot, function, link), {"b": [], "a": [], "d": 0.0})
    r["b"].append(float(before)); r["a"].append(float(after)); r["d"] = max(r["d"], float(diff))
print("| robot | function | link | before ns | after ns | before / after | max difference (relative) |")
print("|---|---|---|--:|--:|--:|--:|")
def cell(v):
    m = statistics.median(v)
    return "%.1f" % m if len(v) == 1 else "%.1f [%.0f-%.0f]" % (m, min(v), max(v))
for (robot, function, link), r in rows.items():
    mb, ma = statistics.median(r["b"]), statistics.median(r["a"])
    print("| %s | %s | %s | %s | %s | %.2f× | %.1e |" % (robot, function, link, cell(r["b"]), cell(r["a"]), mb / ma, r["d"]))
'
} > "$work/table.md"
mv "$work/table.md" "$out"
cat "$out"
