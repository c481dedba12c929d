#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Counts the fine triangulations of the NX x NY x NZ grid (the points of
point_families.h's grid(NX, NY, NZ), in its order) with TOPCOM, using the
grid's symmetries: TOPCOM then enumerates one triangulation per orbit, which
is what makes the 3x3x2 grid countable here, and reports the total.

Prints one JSON line: the points, the order of the symmetry group, the orbits,
the triangulations and the seconds. Exit 0; 2 on bad arguments or when TOPCOM
is missing or fails.

    count_grid_triangulations.py NX NY NZ [--topcom PROGRAM]
"""

import argparse
import itertools
import json
import re
import shutil
import subprocess
import sys
import time


def grid(nx, ny, nz):
    return [(i, j, k) for i in range(nx) for j in range(ny) for k in range(nz)]


def symmetry_generators(nx, ny, nz):
    """The grid's isometries that generate its symmetry group: a reflection per
    axis, and the swap of two axes of the same length."""
    sizes = (nx, ny, nz)
    generators = []
    for axis in range(3):
        if sizes[axis] > 1:
            generators.append(lambda p, a=axis: tuple(sizes[a] - 1 - c if b == a else c for b, c in enumerate(p)))
    for a, b in itertools.combinations(range(3), 2):
        if sizes[a] == sizes[b]:
            generators.append(lambda p, a=a, b=b: tuple(p[b] if c == a else p[a] if c == b else p[c] for c in range(3)))
    return generators


def topcom_input(nx, ny, nz):
    points = grid(nx, ny, nz)
    index = {p: i for i, p in enumerate(points)}
    permutations = [[index[g(p)] for p in points] for g in symmetry_generators(nx, ny, nz)]
    lines = ["[" + ",".join("[%d,%d,%d,1]" % p for p in points) + "]"]
    if permutations:
        lines.append("[" + ",".join("[" + ",".join(map(str, q)) + "]" for q in permutations) + "]")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    for name in ("nx", "ny", "nz"):
        parser.add_argument(name, type=int)
    parser.add_argument("--topcom", default="topcom-points2nallfinetriangs")
    args = parser.parse_args()
    if min(args.nx, args.ny, args.nz) < 2 or args.nx * args.ny * args.nz > 64:
        print("count_grid_triangulations.py: each side has at least 2 points, and at most 64 points in all",
              file=sys.stderr)
        return 2
    if shutil.which(args.topcom) is None:
        print(f"count_grid_triangulations.py: '{args.topcom}' is not installed (Debian: apt-get install topcom)",
              file=sys.stderr)
        return 2
    start = time.monotonic()
    run = subprocess.run([args.topcom, "-v"], input=topcom_input(args.nx, args.ny, args.nz),
                         capture_output=True, text=True)
    seconds = time.monotonic() - start
    total = re.search(r"(\d+) symmetry classes --- (\d+) triangulations in total", run.stderr)
    group = re.search(r"symmetry group with \d+ generators of order (\d+)", run.stderr)
    if run.returncode != 0 or total is None:
        print(f"count_grid_triangulations.py: {args.topcom} failed (exit {run.returncode})", file=sys.stderr)
        return 2
    print(json.dumps({"grid": [args.nx, args.ny, args.nz], "points": args.nx * args.ny * args.nz,
                      "symmetries": int(group.group(1)) if group else 1, "orbits": int(total.group(1)),
                      "triangulations": int(total.group(2)), "seconds": round(seconds, 1)}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
