#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks a tag-bound certificate (tag_bound_closure.h) on its own.

    check_tag_bounds.py CERTIFICATE

Written apart from the package and from trace_checker.h: the Python standard
library only, exact integer arithmetic, cells as sorted point numbers. It
confirms that the certificate's set of states, every triangulation T it lists
with every set of tags within T's bound M(T), holds the start (no tags) and is
closed under every visit of the helper strategy whose tags go with their cells
(until-destroyed; cleared-each-cycle has fewer tags), with help swaps allowed
by a tag on any of a flip's old cells (any-tetrahedron: pass-over's and
facet-cells' swaps are among them), or, when the certificate's reading says
pass-over or facet-cells, by a tag on one of the facet's two cells (then it
covers the 12 readings with those). The rule is monotone in the tags, so each
facet of each T is checked once, with the tags M(T):

  - not locally Delaunay, no flip: its five points' cells are within M(T);
  - not locally Delaunay, a flip: the flipped T' is listed and
    (M(T) + the five points' cells - the old cells) is within M(T');
  - locally Delaunay, a flip, a help swap allowed by M(T): T' is listed and
    M(T) - the old cells is within M(T').

Then that no T is CGAL's triangulation (each has a facet not locally
Delaunay), and that no state of the set ends a run under the ending
no-swap-no-tag: every T has a flip of a facet not locally Delaunay, or the
cells of the five points of those facets are not within M(T), or with just
those tags a help swap of pass-over (a tag on the facet's two cells) is
allowed. So no order at all (fixed, random, adversarial) reaches CGAL's
triangulation from the start under the 24 readings whose tags go with their
cells (the 12 with pass-over or facet-cells, for such a certificate), and
under no-swap-no-tag the run never ends. A certificate whose reading is not
one of those 24 (never-cleared: a destroyed cell's tag comes back with it)
is not read.

Points must be in general position: four coplanar or five cospherical points
met by a visit are reported, not decided (the package perturbs them).

Exit 0: certified. Exit 1: the certificate is wrong (the triangulation, facet
and condition are named). Exit 2: the file cannot be read as a certificate.
"""

import json
import math
import sys
from fractions import Fraction
from itertools import combinations


class Unreadable(Exception):
    pass


class Wrong(Exception):
    pass


def read_certificate(path):
    try:
        with open(path, encoding="utf-8") as f:
            c = json.load(f)
    except OSError as e:
        raise Unreadable(f"cannot read it: {e.strerror}")
    except (json.JSONDecodeError, UnicodeDecodeError) as e:
        raise Unreadable(f"not JSON: {e}")
    version = c.get("version") if isinstance(c, dict) else None
    if (not isinstance(c, dict) or c.get("format") != "Edge_swapping_3 tag-bound certificate" or
            type(version) is not int or version != 1):
        raise Unreadable("not a version 1 tag-bound certificate")
    for key in ("points", "start", "triangulations"):
        if not isinstance(c.get(key), list):
            raise Unreadable(f"'{key}' is not a list")
    points = []
    for k, p in enumerate(c["points"]):
        if not isinstance(p, list) or len(p) != 3 or not all(
                isinstance(x, (int, float)) and not isinstance(x, bool) for x in p):
            raise Unreadable(f"point {k} is not three numbers")
        if not all(math.isfinite(x) and abs(x) <= 1e30 for x in p):
            raise Unreadable(f"point {k} has a coordinate that is not finite or beyond 1e30")
        points.append(tuple(Fraction(x) for x in p))
    if len(points) < 4:
        raise Unreadable("fewer than four points")
    if len(set(points)) != len(points):
        raise Unreadable("two points are the same")

    def cells(value, what):
        if not isinstance(value, list):
            raise Unreadable(f"{what} is not a list of cells")
        out = set()
        for t in value:
            if (not isinstance(t, list) or len(t) != 4 or
                    not all(isinstance(v, int) and not isinstance(v, bool) and 0 <= v < len(points) for v in t)):
                raise Unreadable(f"{what}: a cell that is not four point numbers below {len(points)}")
            if len(set(t)) != 4:
                raise Unreadable(f"{what}: a cell with a repeated point")
            out.add(tuple(sorted(t)))
        if len(out) != len(value):
            raise Unreadable(f"{what}: a cell listed twice")
        return frozenset(out)

    start = cells(c["start"], "start")
    bounds = {}
    for k, entry in enumerate(c["triangulations"]):
        if not isinstance(entry, dict):
            raise Unreadable(f"triangulation {k} is not an object")
        t = cells(entry.get("cells"), f"triangulation {k}")
        if t in bounds:
            raise Unreadable(f"triangulation {k} is listed twice")
        bound = cells(entry.get("tag_bound"), f"the tag bound of triangulation {k}")
        if not bound <= t:
            raise Unreadable(f"the tag bound of triangulation {k} holds a cell that is not one of its cells")
        bounds[t] = bound
    reading = c.get("reading")
    words = reading.split(",") if isinstance(reading, str) else []
    if (len(words) not in (3, 4) or words[0] not in ("until-destroyed", "cleared-each-cycle") or
            words[1] not in ("pass-over", "facet-cells", "any-tetrahedron") or
            words[2] not in ("no-swap-no-tag", "no-swap") or words[3:] not in ([], ["next-cycle"], ["same-cycle"])):
        raise Unreadable("'reading' is not a reading whose tags go with their cells")
    return points, start, bounds, words[1] != "any-tetrahedron"


def integer_points(points):
    # Binary fractions: one power of two makes every coordinate an integer.
    scale = 1
    for p in points:
        for x in p:
            scale = max(scale, x.denominator)
    return [tuple(int(x * scale) for x in p) for p in points]


class Geometry:
    def __init__(self, points):
        self.p = integer_points(points)
        self.orientations = {}
        self.spheres = {}
        # The sign of the in-sphere determinant times the orientation's for a point inside.
        a, b, c, d = (0, 0, 0), (4, 0, 0), (0, 4, 0), (0, 0, 4)
        self.inside_sign = _sign(_insphere(a, b, c, d, (1, 1, 1))) * _sign(_orient(a, b, c, d))

    def orient(self, cell):
        s = self.orientations.get(cell)
        if s is None:
            s = _sign(_orient(*(self.p[v] for v in cell)))
            self.orientations[cell] = s
        return s

    def inside(self, cell, e):
        """Whether point e is strictly inside the sphere of cell (sorted)."""
        key = (cell, e)
        s = self.spheres.get(key)
        if s is None:
            o = self.orient(cell)
            if o == 0:
                raise Wrong(f"cell {list(cell)} is flat")
            det = _sign(_insphere(*(self.p[v] for v in cell), self.p[e]))
            if det == 0:
                raise Wrong(f"points {list(cell)} and {e} are cospherical: not decided here")
            s = det * o == self.inside_sign
            self.spheres[key] = s
        return s


def _sign(x):
    return (x > 0) - (x < 0)


def _det3(m):
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def _orient(a, b, c, d):
    return _det3([[b[i] - a[i] for i in range(3)], [c[i] - a[i] for i in range(3)], [d[i] - a[i] for i in range(3)]])


def _insphere(a, b, c, d, e):
    rows = []
    for q in (a, b, c, d):
        r = [q[i] - e[i] for i in range(3)]
        rows.append(r + [r[0] * r[0] + r[1] * r[1] + r[2] * r[2]])
    # Expansion along the last column.
    total = 0
    for k in range(4):
        minor = [row[:3] for j, row in enumerate(rows) if j != k]
        total += (-1) ** (k + 3) * rows[k][3] * _det3(minor)
    return total


def sorted_cell(*v):
    return tuple(sorted(v))


class Visit:
    """An interior facet f between cells cd and ce (apexes d and e), whether it
    is locally Delaunay, the cells of its five points, and its flip (old and
    new cells; none if it has no flip)."""

    def __init__(self, f, cd, ce, d, e, delaunay, five, old, new):
        self.f, self.cd, self.ce, self.d, self.e = f, cd, ce, d, e
        self.delaunay, self.five, self.old, self.new = delaunay, five, old, new


def visits(geometry, cells):
    """The visit of each interior facet of `cells`."""
    holders = {}
    for t in cells:
        for f in combinations(t, 3):
            holders.setdefault(f, []).append(t)
    out = []
    for f, ts in holders.items():
        if len(ts) > 2:
            raise Wrong(f"facet {list(f)} is in {len(ts)} cells")
        if len(ts) < 2:
            continue
        cd, ce = ts
        d = next(v for v in cd if v not in f)
        e = next(v for v in ce if v not in f)
        delaunay = not geometry.inside(cd, e)
        five = {sorted_cell(*q) for q in combinations(f + (d, e), 4)} & cells
        # Where e is, seen from the cell with d: the sign for each facet point v of the cell with v replaced by e.
        o = geometry.orient(cd)
        signs = {}
        for v in f:
            s = geometry.orient(sorted_cell(*(w for w in cd if w != v), e)) * _parity(cd, v, e) * o
            if s == 0:
                raise Wrong(f"facet {list(f)}: four of its five points are coplanar: not decided here")
            signs[v] = s
        old, new = [], []
        negative = [v for v in f if signs[v] < 0]
        if not negative:  # two cells, convex: 2-3
            old = [cd, ce]
            new = [sorted_cell(*(w for w in cd if w != v), e) for v in f]
        elif len(negative) == 1:  # concave at one edge: 3-2 if the third cell is there
            z = negative[0]
            x, y = (v for v in f if v != z)
            third = sorted_cell(x, y, d, e)
            if third in cells:
                old = [cd, ce, third]
                new = [sorted_cell(x, z, d, e), sorted_cell(y, z, d, e)]
        out.append(Visit(f, cd, ce, d, e, delaunay, five, old, new))
    return out


def _parity(cell, v, e):
    """The sign that turns the orientation of sorted(cell with v replaced by e) into
    that of the cell with e in v's place (the permutation's parity)."""
    placed = [e if w == v else w for w in cell]
    order = sorted(range(4), key=lambda k: placed[k])
    inversions = sum(1 for i in range(4) for j in range(i + 1, 4) if order[i] > order[j])
    return -1 if inversions % 2 else 1


def check(points, start, bounds, narrow):
    """`narrow`: help swaps need a tag on the facet's two cells (pass-over,
    facet-cells), not on any of the flip's old cells (any-tetrahedron)."""
    if start not in bounds:
        raise Wrong("the start is not one of the triangulations")
    geometry = Geometry(points)
    for k, (cells, bound) in enumerate(bounds.items()):
        name = f"triangulation {k}"
        facets = visits(geometry, cells)
        if all(v.delaunay for v in facets):
            raise Wrong(f"{name} is CGAL's triangulation (every facet locally Delaunay)")
        for v in facets:
            where = f"{name}, facet {list(v.f)}"
            old = set(v.old)
            if v.delaunay and not (({v.cd, v.ce} if narrow else old) & bound):
                continue  # no tag that allows a help swap: no swap
            tags = set(bound) | (set() if v.delaunay else v.five)
            if not old:
                if not tags <= bound:
                    raise Wrong(f"{where}: its tags {sorted(tags - bound)} are beyond the bound")
                continue
            after = (cells - old) | set(v.new)
            if after not in bounds:
                raise Wrong(f"{where}: its flip makes a triangulation that is not listed")
            left = tags - old
            if not left <= bounds[after]:
                raise Wrong(f"{where}: after its flip the tags {sorted(left - bounds[after])} are beyond the bound")
        # An end under no-swap-no-tag: every visit inert, with the fewest tags that allow it.
        not_delaunay = [v for v in facets if not v.delaunay]
        if any(v.old for v in not_delaunay):
            continue
        fewest = set().union(*(v.five for v in not_delaunay))
        if not fewest <= bound:
            continue
        if any(v.delaunay and v.old and {v.cd, v.ce} & fewest for v in facets):
            continue
        raise Wrong(f"{name} has a state that ends the run under no-swap-no-tag")
    return len(bounds)


def main(argv):
    if len(argv) != 2:
        print("usage: check_tag_bounds.py CERTIFICATE", file=sys.stderr)
        return 2
    try:
        points, start, bounds, narrow = read_certificate(argv[1])
    except Unreadable as e:
        print(f"check_tag_bounds.py: {argv[1]}: {e}", file=sys.stderr)
        return 2
    try:
        n = check(points, start, bounds, narrow)
    except Wrong as e:
        print(f"check_tag_bounds.py: {argv[1]}: not certified: {e}", file=sys.stderr)
        return 1
    covered = "12 readings with pass-over or facet-cells" if narrow else "24 readings whose tags go with their cells"
    print(f"certified: {n} triangulations, closed under every visit; none is CGAL's triangulation; "
          f"no state ends a run under no-swap-no-tag (the {covered})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
