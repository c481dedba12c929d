#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the Debian packages Edge_swapping_3 needs, only those missing,
# and the packages named as arguments (the fuzz and sanitizer scripts add
# clang). Run as root on Debian 12 (apt-get). Called by the two README commands.
set -euo pipefail

packages=(g++ make cmake libcgal-dev libboost-dev libgmp-dev libmpfr-dev libeigen3-dev catch2 libcli11-dev nlohmann-json3-dev zlib1g-dev python3-matplotlib)
# number_of_threads(n) runs on TBB's threads (as CGAL's parallel algorithms).
packages+=(libtbb-dev)
# The benchmarks compare with TetGen (the program, and its optimizer through libtet) when it is there.
packages+=(tetgen libtet1.5-dev)
# The conjecture laboratory enumerates triangulations with TOPCOM (and its tests do).
packages+=(topcom)
# The suite builds the reference documentation and fails on a warning.
packages+=(doxygen)
packages+=("$@")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
