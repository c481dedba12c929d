#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs edge_swap for the paper's figures and draws them with matplotlib
# (Debian's python3-matplotlib, hence /usr/bin/python3) into doc/Edge_swapping_3/figures/.
# Needs a Release build in build/ (scripts/build_and_demo.sh makes one).
set -euo pipefail
cd "$(dirname "$0")/.."
E=build/bin/edge_swap
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
python3 - "$D/cube.node" <<'PY'
import random, sys
random.seed(1)
with open(sys.argv[1], "w") as f:
    f.write("1000 3 0 0\n")
    for i in range(1000):
        f.write(f"{i + 1} {random.random()!r} {random.random()!r} {random.random()!r}\n")
PY
# Figs. 8 and 9: swaps per cycle, plain and helper, from a placing start.
$E optimize "$D/cube.node" --start placing --criterion delaunay -o "$D/plain.ele" --history "$D/plain.csv" --seed 1
$E optimize "$D/cube.node" --start placing --helper -o "$D/helper.ele" --history "$D/helper.csv" --seed 1
# Fig. 10: dihedral angles of the Delaunay mesh before and after MinMax.
$E optimize "$D/cube.node" --start delaunay --criterion delaunay -o "$D/del.ele"
$E optimize "$D/del.ele" --criterion minmax-dihedral --operations paper-flips -o "$D/minmax.ele" --history "$D/minmax.csv"
$E stats "$D/del.ele" --json "$D/del.json" > /dev/null
$E stats "$D/minmax.ele" --json "$D/minmax.json" > /dev/null
# Fig. 13: worst aspect ratio and sites per round.
$E refine "$D/del.ele" --by aspect-ratio --target 2 -o "$D/ar.ele" --history "$D/fig13.csv"
# Fig. 12: the two-spheres mesh refined by the flow field's gradient.
$E mesh-domain two-spheres -o "$D/ts.mesh"
$E refine "$D/ts.mesh" --by gradient --field flow-density --sites 2000,2000 -o "$D/ts1.mesh"
$E refine "$D/ts.mesh" --by gradient --field flow-speed --sites 0 -o "$D/ts0.vtu"
$E refine "$D/ts1.mesh" --by gradient --field flow-speed --sites 2000,4000,5000 -o "$D/ts2.vtu" --history "$D/fig12.csv"
/usr/bin/python3 doc/Edge_swapping_3/plot_figures.py "$D" doc/Edge_swapping_3/figures
cp "$D/fig13.csv" "$D/fig12.csv" doc/Edge_swapping_3/figures/
/usr/bin/python3 scripts/compact_png.py doc/Edge_swapping_3/figures/*.png
