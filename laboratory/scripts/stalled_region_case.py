#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# A laboratory case (start "cells") that keeps the cells of a region that does
# not fill its points' convex hull, such as the stalled region of the 10^6-point
# run (laboratory/results/stall_helper_1e6/stall_1000000.node/.ele):
# the region's cells as they are, and the rest of the hull filled by TetGen
# with no new point. The region's boundary triangles are given to TetGen as
# facets that it may not split (-p -Y), it tetrahedralizes the hull of the
# points (-c), and its tetrahedra outside the region (in the parts the
# boundary cuts the hull into, the outside and any voids the region encloses:
# one centroid of each part tested exactly against the region's cells) join
# the region's own. The laboratory checks the whole is a triangulation of the
# hull when it reads the case (a bad start is an error).
#
#   stalled_region_case.py NODE ELE OUT.json [SEED [MAX_CYCLES]]
#
# Exit 2, with no output file, when the input cannot be read, the region has
# no boundary, or TetGen adds points or fails.

import collections
import fractions
import json
import math
import os
import subprocess
import sys
import tempfile


class BadInput(Exception):
    """Input that cannot make a case: the message names the file and the problem."""


def fail(message):
    raise BadInput(message)


def read_table(path, width):
    """The rows of a TetGen .node or .ele file: its count, then that many rows of `width` numbers after the index."""
    try:
        with open(path) as f:
            lines = [line.split("#")[0].split() for line in f]
    except OSError as e:
        fail(f"{path}: {e.strerror}")
    lines = [line for line in lines if line]
    if not lines:
        fail(f"{path}: empty")
    try:
        count = int(lines[0][0])
    except ValueError:
        fail(f"{path}, first line: not a count")
    if count != len(lines) - 1:
        fail(f"{path}: the first line says {count} rows, the file has {len(lines) - 1}")
    rows = []
    for number, line in enumerate(lines[1:], start=2):
        if len(line) < width + 1:
            fail(f"{path}, row {number - 1}: fewer than {width} numbers")
        rows.append(line[1:width + 1])
    return rows


def orientation(p, q, r, s):
    """The sign of the determinant of q - p, r - p, s - p."""
    a, b, c = ([u[k] - p[k] for k in range(3)] for u in (q, r, s))
    d = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])
    return (d > 0) - (d < 0)


def inside(x, tet):
    """Whether x is in the closed tetrahedron tet (four exact points)."""
    whole = orientation(*tet)
    return all(orientation(*(tet[:k] + [x] + tet[k + 1:])) * whole >= 0 for k in range(4))


def centroid(exact, cell):
    return [sum(exact[v][k] for v in cell) / 4 for k in range(3)]


def read_region(node, ele):
    """The points (floats) and cells (point indices) of a TetGen .node and .ele pair, checked."""
    # repr of a float read from the file is the same double: the points go out exactly.
    try:
        points = [[float(x) for x in row] for row in read_table(node, 3)]
        cells = [[int(v) for v in row] for row in read_table(ele, 4)]
    except ValueError:
        fail(f"{node} or {ele}: a number that cannot be read")
    if not all(math.isfinite(x) for p in points for x in p):
        fail(f"{node}: a coordinate that is not finite (nan or inf)")
    if len(set(map(tuple, points))) != len(points):
        fail(f"{node}: two points are the same")
    if any(v < 0 or v >= len(points) for cell in cells for v in cell):
        fail(f"{ele}: a vertex index out of range (the node file has {len(points)} points, numbered from 0)")
    return points, cells


def fill_hull(points, cells):
    """The cells of the rest of the points' hull, filled by TetGen around the region `cells`
    with no new point, and a line that says what was done."""
    # The region's boundary: the triangles of exactly one of its cells.
    faces = collections.Counter(tuple(sorted(c[:k] + c[k + 1:])) for c in cells for k in range(4))
    if max(faces.values()) > 2:
        fail("a triangle in more than two cells of the region")
    boundary = [f for f, n in faces.items() if n == 1]
    if not boundary:
        fail("the region has no boundary")
    with tempfile.TemporaryDirectory() as work:
        stem = os.path.join(work, "region")
        with open(stem + ".node", "w") as f:
            f.write(f"{len(points)} 3 0 0\n")
            f.writelines(f"{k} {p[0]!r} {p[1]!r} {p[2]!r}\n" for k, p in enumerate(points))
        with open(stem + ".poly", "w") as f:
            f.write("0 3 0 0\n")  # the points are in region.node
            f.write(f"{len(boundary)} 0\n")
            f.writelines(f"1\n3 {a} {b} {c}\n" for a, b, c in boundary)
            f.write("0\n0\n")
        try:
            subprocess.run(["tetgen", "-pYcQ", stem + ".poly"], check=True, capture_output=True, timeout=600)
        except FileNotFoundError:
            fail("TetGen is not installed (Debian: apt-get install tetgen)")
        except (subprocess.CalledProcessError, subprocess.TimeoutExpired):
            fail("TetGen failed on the region's boundary")
        added = len(read_table(stem + ".1.node", 3)) - len(points)
        if added:
            fail(f"TetGen added {added} points: the rest of the hull has no tetrahedralization without them here")
        tetgen_cells = [([int(v) for v in row[:4]], row[4]) for row in read_table(stem + ".1.ele", 5)]
    # TetGen numbers the parts the kept triangles cut the hull into (-1: outside the closed ones).
    # A part is the region's or fills the rest (the outside, or a void the region encloses): one
    # tetrahedron of it, its centroid in one of the region's cells or not, exactly.
    exact = [[fractions.Fraction(x) for x in p] for p in points]
    first_of_part = {}
    for cell, part in tetgen_cells:
        first_of_part.setdefault(part, cell)
    filling = {part for part, cell in first_of_part.items()
               if not any(inside(centroid(exact, cell), [exact[v] for v in c]) for c in cells)}
    outside = [cell for cell, part in tetgen_cells if part in filling]
    return outside, (f"{len(points)} points, {len(cells)} cells of the region and {len(outside)} filling the rest "
                     f"of the hull ({len(filling)} of TetGen's {len(first_of_part)} parts); {len(boundary)} boundary "
                     f"triangles kept")


def region_case(points, cells, seed, max_cycles):
    """The case (a dict, as the laboratory's case files) and the line that says what was done."""
    outside, said = fill_hull(points, cells)
    return {"points": points, "cells": cells + outside, "start": "cells", "strategy": "helper", "order": "random",
            "seed": seed, "max_cycles": max_cycles}, said


def write_case(case, out):
    with open(out, "w") as f:
        json.dump(case, f)
        f.write("\n")


def main(argv):
    if len(argv) < 4 or len(argv) > 6:
        fail("usage: stalled_region_case.py NODE ELE OUT.json [SEED [MAX_CYCLES]]")
    node, ele, out = argv[1:4]
    try:
        seed = int(argv[4]) if len(argv) > 4 else 1
        max_cycles = int(argv[5]) if len(argv) > 5 else 20000
    except ValueError:
        fail("SEED and MAX_CYCLES are whole numbers")
    points, cells = read_region(node, ele)
    try:
        case, said = region_case(points, cells, seed, max_cycles)
    except BadInput as e:
        fail(f"{ele}: {e}")
    write_case(case, out)
    print(f"{out}: {said}")


if __name__ == "__main__":
    try:
        main(sys.argv)
    except BadInput as e:
        sys.stderr.write(f"stalled_region_case.py: {e}\n")
        sys.exit(2)
