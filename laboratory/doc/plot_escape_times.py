# SPDX-License-Identifier: GPL-3.0-or-later
"""Escape times of the helper strategy in random order: for each point set,
the share of runs (one per seed of the face order) still going at each cycle,
on a log scale, from experiment_escape_times' JSON lines. A run that reached
its cycle limit counts as still going to the end of the plot. A line with
"runs": K stands for K runs that ended alike (a histogram, as kept for the
never-cleared study of results/escape_times/never_cleared_12_points.md).
Usage: /usr/bin/python3 plot_escape_times.py OUT.png LABEL1 FILE1 [LABEL2 FILE2 ...]"""
import json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

def main(out, pairs):
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for label, path in pairs:
        runs = [json.loads(l) for l in open(path)]
        n = sum(r.get("runs", 1) for r in runs)
        cycles = sorted(c for r in runs if r["ending"] == "converged" for c in [r["cycles"]] * r.get("runs", 1))
        limit = max(r["cycles"] for r in runs)
        xs = list(range(0, limit + 1))
        still = []
        k = 0
        for x in xs:
            while k < len(cycles) and cycles[k] <= x:
                k += 1
            still.append((n - k) / n)
        ax.step(xs, [max(s, 0.5 / n) for s in still], where="post",
                label="%s (%d runs; %d not ended by cycle %d)" % (label, n, n - len(cycles), limit))
    ax.set_yscale("log")
    ax.set_xlabel("cycle")
    ax.set_ylabel("share of runs not yet ended")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=130)

if __name__ == "__main__":
    args = sys.argv[2:]
    main(sys.argv[1], list(zip(args[0::2], args[1::2])))
