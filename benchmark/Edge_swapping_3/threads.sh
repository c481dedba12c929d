#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Benchmark (not a test): the worst-first driver on one thread and on more,
# on TetGen's Delaunay triangulations of random points in a cube (fixed
# sequences), as `edge_swap optimize` runs them: MinMax with the topological
# operations and the 140-degree target at 20,000 and 150,000 points (about
# 1.3 x 10^5 and 10^6 cells), the dihedral sine with every operation at
# 8,000 points. Columns: the driver's seconds (from --stats), its speed-up
# over one thread, the process's wall seconds and peak memory, and the cells
# with a dihedral angle below 10 or above 165 degrees (dihedral_counts.py,
# plain Python).
#
#   bash benchmark/Edge_swapping_3/threads.sh [EDGE_SWAP [THREADS...]]   (default build/bin/edge_swap 1 2)
set -euo pipefail
cd "$(dirname "$0")/../.."
program=$(realpath "${1:-build/bin/edge_swap}")
shift || true
threads=("$@")
[ ${#threads[@]} -gt 0 ] || threads=(1 2)
bash scripts/install_dependencies.sh tetgen > /dev/null
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
counts=benchmark/Edge_swapping_3/dihedral_counts.py

runs=(
  "20000|7|--criterion minmax-dihedral --operations topological --quality-target 140"
  "150000|9|--criterion minmax-dihedral --operations topological --quality-target 140"
  "8000|8|--criterion dihedral-sine"
)
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
printf '%-8s %-70s %7s %9s %8s %8s %8s %8s %8s\n' points settings threads driver_s speed-up wall_s peak_MB under10 over165
for run in "${runs[@]}"; do
  IFS='|' read -r n seed settings <<< "$run"
  awk -v n="$n" -v seed="$seed" 'BEGIN { srand(seed); print n, 3, 0, 0; for(i = 1; i <= n; ++i) print i, rand(), rand(), rand() }' \
    > "$dir/p.node"
  (cd "$dir" && tetgen -Q p.node > /dev/null)
  one=""
  for t in "${threads[@]}"; do
    rm -f "$dir/out.ele" "$dir/out.node"
    # shellcheck disable=SC2086
    /usr/bin/time -f '%e %M' -o "$dir/time.txt" "$program" -q optimize "$dir/p.1.ele" -o "$dir/out.ele" $settings \
      --threads "$t" --stats "$dir/s.json" > /dev/null
    seconds=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['seconds'])" "$dir/s.json")
    [ -n "$one" ] || one=$seconds
    read -r wall peak < "$dir/time.txt"
    read -r _ _ _ under _ over _ < <(python3 "$counts" "$dir/out")
    printf '%-8s %-70s %7s %9.2f %8.2f %8.2f %8.0f %8s %8s\n' "$n" "$settings" "$t" "$seconds" \
      "$(python3 -c "print($one / $seconds)")" "$wall" "$((peak / 1024))" "$under" "$over"
  done
done
