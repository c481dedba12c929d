#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Two builds of `edge_swap` side by side on the worst-first driver: the
# driver's own seconds (the report's, no file), each build in turn, ROUNDS
# times, and whether their outputs are the same file. For the table of what
# each step of the driver's speed work gained (benchmarks.md).
#
#   bash benchmark/Edge_swapping_3/optimizer_versions.sh OLD_EDGE_SWAP NEW_EDGE_SWAP [ROUNDS]
#
# Inputs: TetGen's Delaunay triangulation of 20,000 and of 10,000 random
# points (fixed sequences) and the two-spheres mesh (CGAL's Mesh_3).
set -euo pipefail
cd "$(dirname "$0")/../.."
old=$(realpath "$1")
new=$(realpath "$2")
rounds=${3:-3}
bash scripts/install_dependencies.sh tetgen > /dev/null
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for n in 20000 10000; do
  awk -v n=$n 'BEGIN { srand(11); print n, 3, 0, 0; for(i = 1; i <= n; ++i) print i, rand(), rand(), rand() }' \
    > "$dir/random$n.node"
  (cd "$dir" && tetgen -Q "random$n.node" > /dev/null)
done
"$new" -q mesh-domain two-spheres -o "$dir/two_spheres.mesh" > /dev/null

runs=(
  "random20000.1.ele|--criterion minmax-dihedral --operations topological --quality-target 140"
  "random10000.1.ele|--criterion minmax-dihedral --operations topological"
  "two_spheres.mesh|--criterion maxmin-dihedral --operations topological"
  "two_spheres.mesh|--criterion dihedral-sine --operations all"
)
seconds() { sed -n 's/.*; \([0-9.e+-]*\) s$/\1/p'; }
echo "$(nproc) cores, $(date -u +%F), $(uname -m)"
echo "| input | settings | old s | new s | new / old | same output |"
echo "|---|---|---|---|---:|---|"
for run in "${runs[@]}"; do
  mesh=${run%%|*}
  settings=${run#*|}
  old_times=() new_times=()
  for ((k = 0; k < rounds; ++k)); do
    # shellcheck disable=SC2086
    old_times+=("$("$old" -q optimize "$dir/$mesh" -o "$dir/old.mesh" $settings | seconds)")
    # shellcheck disable=SC2086
    new_times+=("$("$new" -q optimize "$dir/$mesh" -o "$dir/new.mesh" $settings | seconds)")
  done
  best() { printf '%s\n' "$@" | sort -g | head -1; }
  o=$(best "${old_times[@]}")
  n=$(best "${new_times[@]}")
  same=no
  cmp -s "$dir/old.mesh" "$dir/new.mesh" && same=yes
  printf '| %s | `%s` | %s (%s) | %s (%s) | %.2f | %s |\n' "$mesh" "$settings" "$o" "${old_times[*]}" "$n" \
    "${new_times[*]}" "$(awk -v a="$n" -v b="$o" 'BEGIN { print a / b }')" "$same"
done
