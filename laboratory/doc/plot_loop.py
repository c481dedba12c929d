# SPDX-License-Identifier: GPL-3.0-or-later
"""Draws a certified loop step by step from a trace (traces.md): the state at
the end of the first round of the loop, then the mesh after each flip until
the state comes back, one panel per flip. The cells a flip removed are drawn
in red in the panel before it, the cells it made in green in its own panel.
The loop is found here as the checker finds it: the first state (cells and
tags) at a round's end that comes back at a later round's end. A mesh of more
than 12 cells is drawn near the flips only: the cells with three or more of
the flips' points. Each panel is scaled to the points drawn.
Usage: /usr/bin/python3 plot_loop.py TRACE.jsonl OUT.png TITLE"""
import json, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

def key(cells):
    return tuple(sorted(tuple(sorted(c)) for c in cells))

def main(trace, out, title):
    lines = [json.loads(l) for l in open(trace)]
    header = lines[0]
    points = header["points"]
    cells = set(key(header["cells"]))
    seen = {}
    steps = []  # (cells before, removed, made, flip) for each flip
    window = None
    flips_since_round = []
    for l in lines[1:]:
        if "facet" in l and l["flip"] is not None:
            removed = set(key(l["cells"]))
            made = set(key(l["created"]))
            flips_since_round.append((set(cells), removed, made, l["flip"], l["facet"]))
            cells = (cells - removed) | made
        elif "round" in l:
            state = (key(l["cells"]), key(l["tagged"]))
            assert set(state[0]) == cells, "the trace's state differs from its flips"
            if state in seen and window is None:
                window = (seen[state], l["round"])
            seen.setdefault(state, l["round"])
            steps.append(flips_since_round)
            flips_since_round = []
    if window is None:
        sys.exit("no state comes back in this trace")
    first, last = window
    loop = [s for r in range(first, last) for s in steps[r]]  # rounds first+1 .. last
    panels = len(loop) + 1
    near = {v for step in loop for c in step[1] | step[2] for v in c}  # the flips' points

    def drawn(c, mesh):
        return len(mesh) <= 12 or sum(v in near for v in c) >= 3

    fig = plt.figure(figsize=(3.2 * panels, 3.6))
    for k in range(panels):
        ax = fig.add_subplot(1, panels, k + 1, projection="3d")
        if k < len(loop):
            mesh, removed, _, _, _ = loop[k]
        else:
            before, removed_last, made_last, _, _ = loop[-1]
            mesh, removed = (before - removed_last) | made_last, set()
        made = loop[k - 1][2] if k > 0 else set()
        shown = [c for c in mesh if drawn(c, mesh)]
        for c in shown:
            colour = "red" if c in removed else ("green" if c in made else "0.8")
            alpha = 0.35 if colour != "0.8" else 0.06
            faces = [[points[c[a]], points[c[b]], points[c[d]]] for a, b, d in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3))]
            ax.add_collection3d(Poly3DCollection(faces, facecolor=colour, edgecolor="0.3", linewidths=0.4, alpha=alpha))
        numbers = sorted({v for c in shown for v in c})
        xs, ys, zs = zip(*(points[n] for n in numbers))
        ax.scatter(xs, ys, zs, color="black", s=8)
        for n in numbers:
            ax.text(*points[n], str(n), fontsize=7)
        for limit, values in ((ax.set_xlim, xs), (ax.set_ylim, ys), (ax.set_zlim, zs)):
            limit(min(values), max(values))
        ax.set_axis_off()
        if k == 0:
            near_only = "" if len(shown) == len(mesh) else "; %d near the flips drawn" % len(shown)
            ax.set_title("after round %d (%d cells%s)" % (first, len(mesh), near_only), fontsize=8)
        else:
            _, _, _, flip, facet = loop[k - 1]
            ax.set_title("flip %d: %s at facet %s" % (k, flip, "-".join(map(str, facet))), fontsize=8)
    fig.suptitle("%s: the state after round %d comes back after round %d" % (title, first, last), fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=130)

if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3])
