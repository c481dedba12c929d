# SPDX-License-Identifier: GPL-3.0-or-later
"""Draws the conjecture laboratory's figures (laboratory/scripts/make_conjecture_figures.sh
runs it): swaps per cycle for 500, 1,000, 8,000 and 10,000 random points,
plain and helper, each normalized to its largest cycle (the paper's Figs. 8
and 9), and the stuck rate of plain swapping against the number of points.
Usage: plot_conjectures.py DATA_DIR OUT_DIR"""
import csv, json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

data, out = sys.argv[1], sys.argv[2]
sizes = (500, 1000, 8000, 10000)

def swaps(name):
    with open(f"{data}/{name}") as f:
        r = list(csv.DictReader(f))
    return [sum(int(x[k]) for k in ("swaps_2_3", "swaps_3_2", "swaps_2_2", "swaps_4_4")) for x in r]

fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
for ax, strategy, title in ((axes[0], "plain", "plain swaps (Algorithm 3)"),
                            (axes[1], "helper", "helper strategy (Algorithm 4)")):
    for n in sizes:
        s = swaps(f"{strategy}_{n}.csv")
        ax.plot(range(1, len(s) + 1), [v / max(s) for v in s], marker="o", ms=2, lw=1, label=f"{n:,} points")
    ax.set_xlabel("cycle over all faces"); ax.set_title(title); ax.legend()
axes[0].set_ylabel("swaps / largest cycle's swaps")
fig.suptitle("Swaps per cycle from a placing start, random points in a cube (Delaunay)")
fig.tight_layout(); fig.savefig(f"{out}/conjecture_swaps_per_cycle.png", dpi=120)

# Stuck rate of plain swapping against size, from the experiment's JSON lines.
stuck, runs = {}, {}
with open(f"{data}/stuck_rate.jsonl") as f:
    for line in f:
        j = json.loads(line)
        n = j["points"]
        runs[n] = runs.get(n, 0) + 1
        stuck[n] = stuck.get(n, 0) + (j["ending"] == "stuck")
ns = sorted(runs)
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(ns, [100.0 * stuck[n] / runs[n] for n in ns], marker="o")
ax.set_xscale("log"); ax.set_xlabel("random points in a cube"); ax.set_ylabel("plain runs stuck (%)")
ax.set_title(f"Plain swapping from placing starts ({runs[ns[0]]} seeds a size)")
fig.tight_layout(); fig.savefig(f"{out}/stuck_rate.png", dpi=120)
