#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs edge_swap for the conjecture laboratory's figures and draws them with
# matplotlib (Debian's python3-matplotlib, hence /usr/bin/python3) into
# laboratory/doc/figures/. Needs a Release build in build/. About 10 minutes here.
set -euo pipefail
cd "$(dirname "$0")/../.."
E=build/bin/edge_swap
L=build/bin/edge_swap_lab
D=$(mktemp -d)
trap 'rm -rf "$D"' EXIT
for n in 500 1000 8000 10000; do
  python3 - "$D/cube_$n.node" "$n" <<'PY'
import random, sys
random.seed(1)
n = int(sys.argv[2])
with open(sys.argv[1], "w") as f:
    f.write(f"{n} 3 0 0\n")
    for i in range(n):
        f.write(f"{i + 1} {random.random()!r} {random.random()!r} {random.random()!r}\n")
PY
  $E optimize "$D/cube_$n.node" --start placing --criterion delaunay -o "$D/plain_$n.ele" --history "$D/plain_$n.csv" --seed 1
  $E optimize "$D/cube_$n.node" --start placing --helper -o "$D/helper_$n.ele" --history "$D/helper_$n.csv" --seed 1
done
$L experiment --families random-cube --sizes 10,20,50,100,200,500,1000 --seeds 1-100 --starts placing \
  --strategies plain --orders random -o "$D/stuck_rate.jsonl" > /dev/null
/usr/bin/python3 laboratory/doc/plot_conjectures.py "$D" laboratory/doc/figures
# The smallest kept cases (test fixtures), run to their end and drawn.
python3 - laboratory/test/fixtures "$D" <<'PY'
import json, sys
fixtures, out = sys.argv[1], sys.argv[2]
for name, stem in (("plain_stuck_9_points.json", "stuck9"), ("helper_storage_cycle_8_points_topcom_start.json", "cycle8")):
    j = json.load(open(f"{fixtures}/{name}"))
    with open(f"{out}/{stem}.node", "w") as f:
        f.write(f"{len(j['points'])} 3 0 0\n")
        for i, p in enumerate(j["points"]):
            f.write(f"{i + 1} {int(p[0])} {int(p[1])} {int(p[2])}\n")
    if "cells" in j:
        with open(f"{out}/{stem}.ele", "w") as f:
            f.write(f"{len(j['cells'])} 4 0\n")
            for i, c in enumerate(j["cells"]):
                f.write(f"{i + 1} {c[0] + 1} {c[1] + 1} {c[2] + 1} {c[3] + 1}\n")
PY
$E optimize "$D/stuck9.node" --start placing:input --criterion delaunay --seed 6012 -o "$D/stuck9_end.ele"
$E optimize "$D/cycle8.ele" --helper --order storage --max-cycles 300 -o "$D/cycle8_end.ele"
/usr/bin/python3 laboratory/doc/plot_cases.py laboratory/doc/figures/smallest_cases.png \
  "Plain swapping stuck (Joe's phenomenon)" "$D/stuck9_end" "Helper strategy in storage order, cycle 300 (still swapping)" "$D/cycle8_end"
/usr/bin/python3 scripts/compact_png.py laboratory/doc/figures/*.png
