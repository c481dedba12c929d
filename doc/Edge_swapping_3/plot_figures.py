# SPDX-License-Identifier: GPL-3.0-or-later
"""Draws the paper's figures for our runs from what edge_swap writes
(scripts/make_figures.sh runs both). Usage: plot_figures.py DATA_DIR OUT_DIR"""
import csv, json, sys, xml.etree.ElementTree as ET
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

# Fig. 10: dihedral-angle histogram before and after MinMax.
fig, ax = plt.subplots(figsize=(6, 4))
for name, label in (("del.json", "Delaunay"), ("minmax.json", "after MinMax swaps")):
    h = json.load(open(f"{data}/{name}"))["dihedral_angle"]
    edges = [h["bin_start"] + h["bin_width"] * k for k in range(len(h["histogram"]))]
    ax.step(edges, h["histogram"], where="post", label=f"{label} (max {h['max']:.1f} deg)")
ax.set_xlabel("dihedral angle (degrees)"); ax.set_ylabel("number of angles"); ax.legend()
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
fig.legend(loc="upper center", bbox_to_anchor=(0.5, 0.9))
fig.tight_layout(); fig.savefig(f"{out}/aspect_ratio_refinement.png", dpi=120)

# Fig. 12: mid-plane slice (|z| small) of the two-spheres mesh, coloured by the field.
def read_vtu(path):
    root = ET.parse(path).getroot()
    arrays = {}
    for section in ("Points", "PointData"):
        for a in root.iter(section):
            for d in a.iter("DataArray"):
                arrays[d.get("Name", section)] = [float(v) for v in d.text.split()]
    return arrays

fig, axes = plt.subplots(2, 1, figsize=(8, 6.5))
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
    ax.tripcolor(t, values, shading="gouraud", cmap="viridis")
    for cx in (0.0, 3.0):
        ax.add_patch(plt.Circle((cx, 0), 0.5, fill=False, lw=0.6, color="w"))
    ax.triplot(t, lw=0.15, color="k")
    ax.set_aspect("equal"); ax.set_title(f"{title}: {len(p) // 3} vertices (slice |z| < 0.08, {field})")
fig.tight_layout(); fig.savefig(f"{out}/two_spheres_slice.png", dpi=120)
