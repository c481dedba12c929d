#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Shrinks a region that keeps random-order helper runs going (such as the
# stalled region of the 10^6-point run) to a small case: removes cells of the
# region, in halves, then quarters and so on down to single cells (ddmin),
# while the case built from the cells left (their points only, the rest of
# their hull filled by TetGen: stalled_region_case.py) still keeps the runs
# going. Deterministic: the runs and TetGen are. Prints each step; writes the
# last case that kept them going.
#
#   shrink_stalled_region.py NODE ELE OUT.json [SEEDS [CYCLES]]    (default 3 seeds, 300 cycles)
#   shrink_stalled_region.py --tag-bounds CASE.json OUT.json
#
# The first keeps every one of SEEDS random-order runs going at cycle CYCLES
# (build/bin/experiment_escape_times, or $EXPERIMENT_ESCAPE_TIMES; the
# package's reading): evidence, not proof. The second keeps what is proved:
# no order at all reaches CGAL's triangulation from the case, under the 24
# readings whose tags go with their cells (the tag-bound set of
# build/bin/experiment_adversarial_orders --tag-bounds, or
# $EXPERIMENT_ADVERSARIAL_ORDERS, under until-destroyed,any-tetrahedron,
# no-swap-no-tag, closes with no Delaunay triangulation in it). It starts
# from all the cells of CASE.json (start "cells") and shrinks again from each
# result, while a round leaves fewer points; it writes the last case that had
# fewer points than the one before.

import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stalled_region_case as region  # noqa: E402

BIN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "build", "bin")


def subcase(points, cells):
    """The case of `cells` alone: their points, renumbered in the order they come."""
    used = sorted({v for c in cells for v in c})
    number = {v: k for k, v in enumerate(used)}
    return [points[v] for v in used], [[number[v] for v in c] for c in cells]


def main(argv):
    if len(argv) == 4 and argv[1] == "--tag-bounds":
        return shrink_tag_bounds(argv[2], argv[3])
    if len(argv) < 4 or len(argv) > 6:
        region.fail("usage: shrink_stalled_region.py NODE ELE OUT.json [SEEDS [CYCLES]]\n"
                    "       shrink_stalled_region.py --tag-bounds CASE.json OUT.json")
    node, ele, out = argv[1:4]
    try:
        seeds = int(argv[4]) if len(argv) > 4 else 3
        cycles = int(argv[5]) if len(argv) > 5 else 300
    except ValueError:
        region.fail("SEEDS and CYCLES are whole numbers")
    if seeds < 1 or cycles < 1:
        region.fail("SEEDS and CYCLES are at least 1")
    program = os.environ.get("EXPERIMENT_ESCAPE_TIMES", os.path.join(BIN, "experiment_escape_times"))
    points, cells = region.read_region(node, ele)
    t0 = time.time()

    def going(path):
        """Whether every run from the case at `path` is going at the limit."""
        run = subprocess.run([program, path, "1", str(seeds), str(cycles), "1"], capture_output=True, text=True)
        if run.returncode != 0:
            return False
        ends = [json.loads(line)["ending"] for line in run.stdout.splitlines() if line.strip()]
        return len(ends) == seeds and all(e == "cycle limit reached" for e in ends)

    kept = ddmin(points, cells, cycles, going, t0)
    if kept is None:
        region.fail(f"from the whole region not all of {seeds} runs are going at cycle {cycles}")
    case, said = region.region_case(*subcase(points, kept), 1, cycles)
    region.write_case(case, out)
    print(f"{out}: {said}; every one of {seeds} runs still going at cycle {cycles}, and without any one of "
          f"the {len(kept)} cells not ({time.time() - t0:.0f} s)")


def ddmin(points, cells, cycles, keeps, t0):
    """The cells left by ddmin while the case of the cells left `keeps` (a test
    on the case file's path); None if the whole region does not."""

    def test(kept, path):
        try:
            case, _ = region.region_case(*subcase(points, kept), 1, cycles)
        except region.BadInput:
            return False  # TetGen cannot fill the rest, or the cells left are not a region
        region.write_case(case, path)
        return keeps(path)

    with tempfile.TemporaryDirectory() as work:
        trial = os.path.join(work, "trial.json")
        if not test(cells, trial):
            return None
        kept, parts = cells, 2
        while len(kept) > 1:
            size = (len(kept) + parts - 1) // parts
            chunks = [kept[k:k + size] for k in range(0, len(kept), size)]
            for k in range(len(chunks)):
                rest = [c for j, chunk in enumerate(chunks) if j != k for c in chunk]
                if test(rest, trial):
                    kept, parts = rest, max(parts - 1, 2)
                    print(f"{time.time() - t0:.0f} s: {len(kept)} cells of the region kept, "
                          f"{len({v for c in kept for v in c})} points", flush=True)
                    break
            else:
                if parts >= len(kept):
                    break
                parts = min(len(kept), 2 * parts)
    return kept


def shrink_tag_bounds(source, out):
    """Rounds of ddmin under the proof that no order reaches CGAL's triangulation."""
    program = os.environ.get("EXPERIMENT_ADVERSARIAL_ORDERS", os.path.join(BIN, "experiment_adversarial_orders"))
    reading = "until-destroyed,any-tetrahedron,no-swap-no-tag"

    def trapped(path):
        run = subprocess.run([program, "--tag-bounds", path, reading, "20000"], capture_output=True, text=True)
        return run.returncode == 0 and run.stdout.rstrip().endswith("no order reaches CGAL's triangulation from 1")

    try:
        with open(source, encoding="utf-8") as f:
            case = json.load(f)
        if case.get("start") != "cells":
            raise ValueError('its start is not "cells"')
        points = [[float(x) for x in p] for p in case["points"]]
        cells = [[int(v) for v in c] for c in case["cells"]]
    except (OSError, ValueError, KeyError, TypeError) as e:
        region.fail(f"{source}: not a case file with its cells: {e}")
    first = subprocess.run([program, "--tag-bounds", source, reading, "20000"], capture_output=True, text=True)
    if first.returncode != 0:  # the program's own reason: points it refuses, cells that are no triangulation
        region.fail(first.stderr.strip() or f"{source}: {program} ended with {first.returncode}")
    if not trapped(source):
        region.fail(f"{source}: its tag-bound set holds CGAL's triangulation (or does not close): nothing to keep")
    t0 = time.time()
    best = None
    while True:
        kept = ddmin(points, cells, 300, trapped, t0)
        if kept is None:  # not expected: the case of all the cells is the one before
            break
        case, said = region.region_case(*subcase(points, kept), 1, 300)
        if len(case["points"]) >= len(points):
            break
        best = case, said
        print(f"round: {said}", flush=True)
        points, cells = case["points"], case["cells"]
    if best is None:  # no point removed: the case itself, with the rest filled again
        best = region.region_case(points, cells, 1, 300)
    region.write_case(best[0], out)
    print(f"{out}: {best[1]}; no order reaches CGAL's triangulation from it ({time.time() - t0:.0f} s)")

if __name__ == "__main__":
    try:
        main(sys.argv)
    except region.BadInput as e:
        sys.stderr.write(f"shrink_stalled_region.py: {e}\n")
        sys.exit(2)
