#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The SHA-256 of what `edge_swap optimize` writes, on the test fixtures and
# on meshes that Gmsh, TetGen and CGAL make from their own examples (as
# real_meshes.sh makes them), under the worst-first driver's settings users
# pick. Two builds that print the same lines made the same meshes, cell for
# cell and digit for digit: run it on each and compare with diff.
#
#   bash benchmark/Edge_swapping_3/optimizer_output_hashes.sh [EDGE_SWAP] > hashes.txt
#
# EDGE_SWAP defaults to build/bin/edge_swap. Each line: hash, mesh, settings.
# THREADS=N adds --threads N to every run (THREADS=1 compares a build that
# has --threads with one from before it, which ran on one thread).
set -euo pipefail
cd "$(dirname "$0")/../.."
program=$(realpath "${1:-build/bin/edge_swap}")
threads=${THREADS:+--threads $THREADS}
bash scripts/install_dependencies.sh gmsh gmsh-doc tetgen libcgal-demo > /dev/null
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
bash benchmark/Edge_swapping_3/make_real_meshes.sh "$dir" tutorial/t5 tutorial/t16 demos/boolean/boolean \
  demos/boolean/compsolid > "$dir/meshes.txt"
mapfile -t meshes < "$dir/meshes.txt"
# TetGen's Delaunay triangulation of 3,000 random points (a fixed sequence).
awk 'BEGIN { srand(7); print 3000, 3, 0, 0; for(i = 1; i <= 3000; ++i) print i, rand(), rand(), rand() }' \
  > "$dir/random.node"
(cd "$dir" && tetgen -Q random.node > /dev/null)
meshes+=("$dir/random.1.ele")

settings=(
  ""                                                                        # dihedral sine, every operation
  "--criterion minmax-dihedral --operations topological --quality-target 140"
  "--criterion maxmin-dihedral --operations topological"
  "--criterion radius-ratio --operations all,vertex-removal,vertex-insertion"
  "--criterion dihedral-sine --operations all,boundary-smoothing --angle-range free"
)
for mesh in "${meshes[@]}"; do
  for s in "${settings[@]}"; do
    rm -f "$dir/out.mesh"
    # shellcheck disable=SC2086
    "$program" -q optimize "$mesh" -o "$dir/out.mesh" $s $threads > "$dir/report.txt"
    printf '%s  %s  %s\n' "$(sha256sum < "$dir/out.mesh" | cut -c1-16)" "$(basename "$mesh")" "${s:-(defaults)}"
  done
done
# Point sets: the program starts them and optimizes under a quality criterion.
for node in test/Edge_swapping_3/fixtures/cospherical_199_points.node \
            test/Edge_swapping_3/fixtures/helper_storage_order_cycle_300.node; do
  rm -f "$dir/out.mesh"
  # shellcheck disable=SC2086
  "$program" -q optimize "$node" -o "$dir/out.mesh" --criterion minmax-dihedral --operations all $threads > "$dir/report.txt"
  printf '%s  %s  %s\n' "$(sha256sum < "$dir/out.mesh" | cut -c1-16)" "$(basename "$node")" "--criterion minmax-dihedral --operations all"
done
