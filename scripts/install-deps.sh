#!/usr/bin/env bash
# Install the Debian packages rbdgen needs, only those missing. Works as root, or as a user with sudo.
set -euo pipefail

packages=(g++ cmake ninja-build pkg-config libeigen3-dev libxsimd-dev liburdfdom-dev libtinyxml2-dev libfmt-dev libcli11-dev
          libgtest-dev libgmock-dev libbenchmark-dev gnuplot-nox
          pybind11-dev python3-dev python3-numpy python3-pytest)
packages+=("$@")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
echo "rbdgen: installing ${missing[*]}" >&2
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
