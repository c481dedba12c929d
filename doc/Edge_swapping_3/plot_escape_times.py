# SPDX-License-Identifier: GPL-3.0-or-later
"""Escape times of the helper strategy in random order: for each point set,
the share of runs (one per seed of the face order) still going at each cycle,
on a log scale, from experiment_escape_times' JSON lines.
Usage: /usr/bin/python3 plot_escape_times.py OUT.png LABEL1 FILE1 [LABEL2 FILE2 ...]"""
import json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

def main(out, pairs):
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for label, path in pairs:
        runs = [json.loads(l) for l in open(path)]
        cycles = sorted(r["cycles"] for r in runs)
        n = len(cycles)
        xs = list(range(0, cycles[-1] + 2))
        still = []
        k = 0
        for x in xs:
            while k < n and cycles[k] <= x:
                k += 1
            still.append((n - k) / n)
        ax.step(xs, [max(s, 0.5 / n) for s in still], where="post",
                label="%s (%d seeds, longest %d cycles)" % (label, n, cycles[-1]))
    ax.set_yscale("log")
    ax.set_xlabel("cycle")
    ax.set_ylabel("share of runs not yet ended")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=130)

if __name__ == "__main__":
    args = sys.argv[2:]
    main(sys.argv[1], list(zip(args[0::2], args[1::2])))
