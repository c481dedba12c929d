#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# The cells of a TetGen mesh (BASE.node, BASE.ele) with a dihedral angle
# below 10 or above 165 degrees, and the extreme angles: an independent
# count (plain Python, no code of the package) for the benchmark scripts.
#
#   python3 dihedral_counts.py BASE    ->  "cells N under10 A over165 B min X max Y"
import math
import sys


def read(base):
    with open(base + ".node") as f:
        lines = [l.split() for l in f if l.strip() and not l.startswith("#")]
    n = int(lines[0][0])
    first = int(lines[1][0])
    points = [tuple(float(x) for x in l[1:4]) for l in lines[1:1 + n]]
    with open(base + ".ele") as f:
        lines = [l.split() for l in f if l.strip() and not l.startswith("#")]
    m = int(lines[0][0])
    cells = [tuple(int(x) - first for x in l[1:5]) for l in lines[1:1 + m]]
    return points, cells


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dihedral_angles(p):
    angles = []
    for a, b, c, d in ((0, 1, 2, 3), (0, 2, 1, 3), (0, 3, 1, 2), (1, 2, 0, 3), (1, 3, 0, 2), (2, 3, 0, 1)):
        e = sub(p[b], p[a])
        n1 = cross(e, sub(p[c], p[a]))
        n2 = cross(e, sub(p[d], p[a]))
        den = math.sqrt(sum(x * x for x in n1) * sum(x * x for x in n2))
        cos = sum(x * y for x, y in zip(n1, n2)) / den
        angles.append(math.degrees(math.acos(max(-1.0, min(1.0, cos)))))
    return angles


points, cells = read(sys.argv[1])
under = over = 0
low, high = 180.0, 0.0
for t in cells:
    a = dihedral_angles([points[k] for k in t])
    under += min(a) < 10
    over += max(a) > 165
    low, high = min(low, min(a)), max(high, max(a))
print(f"cells {len(cells)} under10 {under} over165 {over} min {low:.3f} max {high:.3f}")
