#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Shrinks a region that keeps random-order helper runs going (such as the
# stalled region of the 10^6-point run) to a small case: removes cells of the
# region, in halves, then quarters and so on down to single cells (ddmin),
# while the case built from the cells left (their points only, the rest of
# their hull filled by TetGen: stalled_region_case.py) still has every one of
# SEEDS random-order runs going at cycle CYCLES (experiment_escape_times, the
# package's reading). Deterministic: the runs are. Prints each step; writes
# the last case that kept them going.
#
#   shrink_stalled_region.py NODE ELE OUT.json [SEEDS [CYCLES]]    (default 3 seeds, 300 cycles)
#
# The program is build/bin/experiment_escape_times, or $EXPERIMENT_ESCAPE_TIMES.

import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stalled_region_case as region  # noqa: E402


def subcase(points, cells):
    """The case of `cells` alone: their points, renumbered in the order they come."""
    used = sorted({v for c in cells for v in c})
    number = {v: k for k, v in enumerate(used)}
    return [points[v] for v in used], [[number[v] for v in c] for c in cells]


def main(argv):
    if len(argv) < 4 or len(argv) > 6:
        region.fail("usage: shrink_stalled_region.py NODE ELE OUT.json [SEEDS [CYCLES]]")
    node, ele, out = argv[1:4]
    try:
        seeds = int(argv[4]) if len(argv) > 4 else 3
        cycles = int(argv[5]) if len(argv) > 5 else 300
    except ValueError:
        region.fail("SEEDS and CYCLES are whole numbers")
    if seeds < 1 or cycles < 1:
        region.fail("SEEDS and CYCLES are at least 1")
    program = os.environ.get("EXPERIMENT_ESCAPE_TIMES", os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "build", "bin", "experiment_escape_times"))
    points, cells = region.read_region(node, ele)
    t0 = time.time()

    def going(kept, path):
        """Whether every run from the case of `kept` is going at the limit (the case written to `path`)."""
        try:
            case, _ = region.region_case(*subcase(points, kept), 1, cycles)
        except region.BadInput:
            return False  # TetGen cannot fill the rest, or the cells left are not a region
        region.write_case(case, path)
        run = subprocess.run([program, path, "1", str(seeds), str(cycles), "1"], capture_output=True, text=True)
        if run.returncode != 0:
            return False
        ends = [json.loads(line)["ending"] for line in run.stdout.splitlines() if line.strip()]
        return len(ends) == seeds and all(e == "cycle limit reached" for e in ends)

    with tempfile.TemporaryDirectory() as work:
        trial = os.path.join(work, "trial.json")
        if not going(cells, trial):
            region.fail(f"from the whole region not all of {seeds} runs are going at cycle {cycles}")
        kept, parts = cells, 2
        while len(kept) > 1:
            size = (len(kept) + parts - 1) // parts
            chunks = [kept[k:k + size] for k in range(0, len(kept), size)]
            for k in range(len(chunks)):
                rest = [c for j, chunk in enumerate(chunks) if j != k for c in chunk]
                if going(rest, trial):
                    kept, parts = rest, max(parts - 1, 2)
                    print(f"{time.time() - t0:.0f} s: {len(kept)} cells of the region kept, "
                          f"{len({v for c in kept for v in c})} points", flush=True)
                    break
            else:
                if parts >= len(kept):
                    break
                parts = min(len(kept), 2 * parts)
    case, said = region.region_case(*subcase(points, kept), 1, cycles)
    region.write_case(case, out)
    print(f"{out}: {said}; every one of {seeds} runs still going at cycle {cycles}, and without any one of "
          f"the {len(kept)} cells not ({time.time() - t0:.0f} s)")


if __name__ == "__main__":
    try:
        main(sys.argv)
    except region.BadInput as e:
        sys.stderr.write(f"shrink_stalled_region.py: {e}\n")
        sys.exit(2)
