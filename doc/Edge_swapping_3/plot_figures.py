# SPDX-License-Identifier: GPL-3.0-or-later
"""Draws the paper's figures for our runs from what edge_swap writes
(scripts/make_figures.sh runs both). Usage: plot_figures.py DATA_DIR OUT_DIR"""
import collections, csv, itertools, json, math, sys, xml.etree.ElementTree as ET
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri

data, out = sys.argv[1], sys.argv[2]

def rows(name):
    with open(f"{data}/{name}") as f:
        return list(csv.DictReader(f))

def total_swaps(r):
    return sum(int(r[k]) for k in ("swaps_2_3", "swaps_3_2", "swaps_2_2", "swaps_4_4"))

# Figs. 8 and 9: swaps per cycle, normalized to the same maximum.
fig, ax = plt.subplots(figsize=(6, 4))
for name, label in (("plain.csv", "plain swaps (Algorithm 3)"), ("helper.csv", "helper strategy (Algorithm 4)")):
    r = rows(name)
    s = [total_swaps(x) for x in r]
    ax.plot([int(x["cycle"]) for x in r], [v / max(s) for v in s], marker="o", ms=3, label=label)
ax.set_xlabel("cycle over all faces"); ax.set_ylabel("swaps / largest cycle's swaps")
ax.set_title("Swaps per cycle, 1,000 random points, placing start"); ax.legend()
fig.tight_layout(); fig.savefig(f"{out}/swaps_per_cycle.png", dpi=120)

# Fig. 10: dihedral-angle histogram before and after MinMax, with the largest
# angle of the cells with a hull facet apart from that of the others (the
# angles near 180 degrees are flat slivers in the layer of points along the
# hull).
def read_mesh(stem):
    with open(f"{data}/{stem}.node") as f:
        head = f.readline().split()
        pts = {}
        for _ in range(int(head[0])):
            w = f.readline().split()
            pts[int(w[0])] = tuple(float(v) for v in w[1:4])
    with open(f"{data}/{stem}.ele") as f:
        n = int(f.readline().split()[0])
        cells = [tuple(int(v) for v in f.readline().split()[1:5]) for _ in range(n)]
    return pts, cells

def largest_dihedral(a, b, c, d):
    sub = lambda u, v: (u[0] - v[0], u[1] - v[1], u[2] - v[2])
    cross = lambda u, v: (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    dot = lambda u, v: u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
    p = (a, b, c, d)
    worst = 0.0
    for i in range(4):
        for j in range(i + 1, 4):
            k, l = [m for m in range(4) if m not in (i, j)]
            e = sub(p[j], p[i])
            n1 = cross(e, sub(p[k], p[i])); n2 = cross(e, sub(p[l], p[i]))
            cosine = dot(n1, n2) / math.sqrt(dot(n1, n1) * dot(n2, n2))
            worst = max(worst, math.degrees(math.acos(max(-1.0, min(1.0, cosine)))))
    return worst

def largest_by_side(stem):
    pts, cells = read_mesh(stem)
    count = collections.Counter(tuple(sorted(f)) for c in cells for f in itertools.combinations(c, 3))
    hull, inner = 0.0, 0.0
    for c in cells:
        angle = largest_dihedral(*(pts[v] for v in c))
        on_hull = any(count[tuple(sorted(f))] == 1 for f in itertools.combinations(c, 3))
        if on_hull: hull = max(hull, angle)
        else: inner = max(inner, angle)
    return hull, inner

fig, ax = plt.subplots(figsize=(6, 4))
for name, stem, label in (("del.json", "del", "Delaunay"), ("minmax.json", "minmax", "after MinMax swaps")):
    h = json.load(open(f"{data}/{name}"))["dihedral_angle"]
    edges = [h["bin_start"] + h["bin_width"] * k for k in range(len(h["histogram"]))]
    hull, inner = largest_by_side(stem)
    ax.step(edges, h["histogram"], where="post",
            label=f"{label}: max {hull:.1f} (cells on the hull), {inner:.1f} (others)")
ax.set_xlabel("dihedral angle (degrees)"); ax.set_ylabel("number of angles"); ax.legend(fontsize=8)
ax.set_title("Dihedral angles, 1,000 random points")
fig.tight_layout(); fig.savefig(f"{out}/dihedral_histogram.png", dpi=120)

# Fig. 13: worst aspect ratio of refinable cells, and sites, per round.
r = rows("fig13.csv")
fig, ax = plt.subplots(figsize=(6, 4))
rounds = [int(x["round"]) for x in r]
ax.plot(rounds, [float(x["worst_refinable_aspect_ratio"]) for x in r], "-o", ms=3, label="worst refinable aspect ratio")
ax.set_xlabel("round (pass over all cells)"); ax.set_ylabel("longest / shortest edge")
ax2 = ax.twinx()
ax2.plot(rounds, [int(x["vertices"]) for x in r], ":", color="gray", label="sites")
ax2.set_ylabel("sites in the mesh")
ax.set_title("Refinement at circumcenters to aspect ratio 2")
# The legend goes below the axes, clear of both curves.
fig.legend(loc="lower center", ncol=2, frameon=False)
fig.tight_layout(rect=(0, 0.07, 1, 1)); fig.savefig(f"{out}/aspect_ratio_refinement.png", dpi=120)

# Fig. 12: mid-plane slice (|z| small) of the two-spheres mesh, coloured by the field.
def read_vtu(path):
    root = ET.parse(path).getroot()
    arrays = {}
    for section in ("Points", "PointData"):
        for a in root.iter(section):
            for d in a.iter("DataArray"):
                arrays[d.get("Name", section)] = [float(v) for v in d.text.split()]
    return arrays

fig, axes = plt.subplots(2, 1, figsize=(8.8, 6.5))
for ax, name, title in ((axes[0], "ts0.vtu", "Mesh_3 mesh"), (axes[1], "ts2.vtu", "after 15,000 sites by gradient")):
    a = read_vtu(f"{data}/{name}")
    p = a["Points"]
    field = "flow-speed"
    idx = [k for k in range(len(p) // 3) if abs(p[3 * k + 2]) < 0.08]
    x = [p[3 * k] for k in idx]; y = [p[3 * k + 1] for k in idx]
    values = [a[field][k] for k in idx]
    t = mtri.Triangulation(x, y)
    # The spheres (radius 0.5 at x = 0 and 3) are holes of the mesh: leave them blank.
    t.set_mask([min((sum(x[i] for i in tri) / 3 - cx) ** 2 + (sum(y[i] for i in tri) / 3) ** 2
                    for cx in (0.0, 3.0)) < 0.25 for tri in t.triangles])
    shaded = ax.tripcolor(t, values, shading="gouraud", cmap="viridis")
    fig.colorbar(shaded, ax=ax, label="flow speed (free stream 1)", shrink=0.9)
    for cx in (0.0, 3.0):
        ax.add_patch(plt.Circle((cx, 0), 0.5, fill=False, lw=0.6, color="w"))
    ax.triplot(t, lw=0.15, color="k")
    ax.set_aspect("equal"); ax.set_title(f"{title}: {len(p) // 3} vertices (slice |z| < 0.08, {field})")
fig.tight_layout(); fig.savefig(f"{out}/two_spheres_slice.png", dpi=120)
