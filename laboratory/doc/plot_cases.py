# SPDX-License-Identifier: GPL-3.0-or-later
"""Draws the smallest kept cases of the conjecture laboratory: each mesh with
its facets that are not locally Delaunay in red. The meshes are the ends of the
runs in conjectures.md (TetGen .node/.ele with integer coordinates, so the
in-sphere tests here are exact integer arithmetic).
Usage: plot_cases.py OUT.png TITLE1 STEM1 TITLE2 STEM2"""
import itertools, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

def read(stem):
    with open(stem + ".node") as f:
        lines = [l.split() for l in f if l.strip() and not l.startswith("#")]
    pts = {int(l[0]): tuple(int(float(x)) for x in l[1:4]) for l in lines[1:]}
    with open(stem + ".ele") as f:
        lines = [l.split() for l in f if l.strip() and not l.startswith("#")]
    tets = [tuple(int(x) for x in l[1:5]) for l in lines[1:]]
    return pts, tets

def det(m):
    if len(m) == 1:
        return m[0][0]
    return sum((-1) ** j * m[0][j] * det([r[:j] + r[j + 1:] for r in m[1:]]) for j in range(len(m)))

def orient(a, b, c, d):
    return det([[b[k] - a[k] for k in range(3)], [c[k] - a[k] for k in range(3)], [d[k] - a[k] for k in range(3)]])

def lifted(t, e):
    return det([[p[k] - e[k] for k in range(3)] + [sum((p[k] - e[k]) ** 2 for k in range(3))] for p in t])

# The sign of `lifted` for a point inside a positively oriented tetrahedron.
REF = ((0, 0, 0), (4, 0, 0), (0, 4, 0), (0, 0, 4))
INSIDE = 1 if lifted(REF, (1, 1, 1)) * orient(*REF) > 0 else -1

def inside(t, e):
    return lifted(t, e) * orient(*t) * INSIDE > 0

def non_delaunay_facets(pts, tets):
    by_facet = {}
    for t in tets:
        for f in itertools.combinations(t, 3):
            by_facet.setdefault(frozenset(f), []).append(t)
    bad = []
    for f, ts in by_facet.items():
        if len(ts) == 2:
            apex = [v for v in ts[1] if v not in f][0]
            if inside([pts[v] for v in ts[0]], pts[apex]):
                bad.append(f)
    return bad

out = sys.argv[1]
cases = list(zip(sys.argv[2::2], sys.argv[3::2]))
fig = plt.figure(figsize=(6 * len(cases), 5.5))
for k, (title, stem) in enumerate(cases):
    pts, tets = read(stem)
    ax = fig.add_subplot(1, len(cases), k + 1, projection="3d")
    edges = {frozenset(e) for t in tets for e in itertools.combinations(t, 2)}
    for e in edges:
        a, b = (pts[v] for v in e)
        ax.plot(*zip(a, b), color="0.6", lw=0.7)
    bad = non_delaunay_facets(pts, tets)
    ax.add_collection3d(Poly3DCollection([[pts[v] for v in f] for f in bad], facecolor="red", alpha=0.35,
                                         edgecolor="darkred"))
    xs, ys, zs = zip(*pts.values())
    ax.scatter(xs, ys, zs, color="k", s=12)
    for v, p in pts.items():
        ax.text(*p, str(v), fontsize=8)
    ax.set_title(f"{title}\n{len(pts)} points, {len(tets)} tetrahedra, {len(bad)} facets not Delaunay (red)", fontsize=9)
    ax.set_xticks([]); ax.set_yticks([]); ax.set_zticks([])
fig.tight_layout(); fig.savefig(out, dpi=110)
