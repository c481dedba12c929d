#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# README command 2: install what is missing, build what the tests need in
# Release, run the test suite (every test but those labelled `extended`).
#   --extended   also build the examples, the benchmarks, the laboratory and
#                the tests of CGAL's domain meshes, and run the tests labelled
#                `extended` (the laboratory, headers compiled alone, install,
#                examples, CGAL's domain meshes).
# Prints the seconds each step took.
set -euo pipefail
cd "$(dirname "$0")/.."
extended=OFF
case "${1:-}" in
  "") ;;
  --extended) extended=ON ;;
  *) echo "build_and_test.sh: unknown option '$1' (known: --extended)" >&2; exit 2 ;;
esac
step() { # NAME COMMAND...: runs it and says how long it took
  local name=$1 start=$SECONDS
  shift
  "$@"
  echo "build_and_test.sh: $name took $((SECONDS - start)) s"
}
# The extended tests start a Slurm cluster of one node and run GNU parallel.
cluster_packages=()
[ $extended = OFF ] || cluster_packages=(slurmctld slurmd slurm-client munge parallel)
step "installing what is missing" bash scripts/install_dependencies.sh "${cluster_packages[@]}"
step "configuring" cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DEDGE_SWAPPING_3_BUILD_EXAMPLES=$extended \
  -DEDGE_SWAPPING_3_BUILD_BENCHMARKS=$extended -DEDGE_SWAPPING_3_BUILD_LABORATORY=$extended \
  -DEDGE_SWAPPING_3_BUILD_EXTENDED_TESTS=$extended
step "building" cmake --build build -j "$(nproc)"
if [ $extended = ON ]; then
  step "the extended tests" ctest --test-dir build --output-on-failure -j "$(nproc)" -L extended
else
  step "the tests" ctest --test-dir build --output-on-failure -j "$(nproc)" -LE extended
fi
