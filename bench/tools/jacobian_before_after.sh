#!/usr/bin/env bash
# The Jacobian of one link from q, before and after it walked only the link's support path (issue
# 14's goal: >= 3x on solo12 and talos_reduced with a free base): before_after.sh with the headers
# of the generator at commit 622c618 (before that work: jacobian(body, q) computed the kinematics of
# every link, then the link's Jacobian).
#   bench/tools/jacobian_before_after.sh RBDGEN OUT.md [CXX]
# (RBDGEN_BEFORE=path: an rbdgen already built at 622c618, instead of building one.)
set -euo pipefail
BEFORE=622c618 ROBOTS="solo12+free:HR_LOWER_LEG,HR_FOOT talos_reduced+free:leg_right_6_link,right_sole_link" \
  FUNCTIONS="jacobian(body, q)" TITLE="jacobian(body, q) before and after the support-path walk" \
  exec "$(dirname "${BASH_SOURCE[0]}")/before_after.sh" "$@"
