#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Reads the output directories of certify_fixed_order_loops.sh (one file per
# reading, and progress.txt) and prints a Markdown table: per reading, the
# runs, those still swapping at the cycle limit, the loops the checker
# certified among them, those of them that ended later (traced past the limit:
# on CGAL's triangulation or stuck) or were still going at the trace limit with
# no state repeated, those stuck, and the seconds the reading took. The
# directories may be of different point sets (one per set of a family) or
# shards (--shard I/N) of one: a reading's counts are summed over them, and a
# line below the table says which shards of how many it added up.
# Readings not complete in every directory are listed as missing. Exit 1 if a
# run at the limit was neither certified a loop nor seen to end, so that no
# such claim goes unnoticed. Directories run with a priority per start
# (--order-seeds per-start) sample other orders than those run with the set's
# seed: given both, it exits 2 and names one of each. So does it for shards
# that do not partition one set's starts together: the same shard twice, a
# whole run beside a shard, or shards of other partitions (other N, or modulo
# N beside blocks of B: --stream-batch). The set is read from progress.txt
# (SPEC seeds A-B), the shard from each file's first line.
#
#   summarize_certified_loops.py OUTDIR [OUTDIR ...]

import collections
import os
import re
import subprocess
import sys

LINE = re.compile(r"^all seeds: (\d+) runs, (\d+) still swapping \((\d+) loops certified by the checker\), (\d+) stuck$")
LATER = re.compile(r"^at the limit, not certified: (\d+) ended after cycle \d+ on CGAL's triangulation, "
                   r"(\d+) ended stuck after it, (\d+) still swapping at cycle \d+ with no state repeated$")
TIME = re.compile(r"^.*, ([a-z-]+,[a-z-]+,[a-z-]+(?:,same-cycle)?): (\d+) s, ")
POINT_SET = re.compile(r"^(.*? seeds [^ ,]+)")
SHARD = re.compile(r", shard (\d+)/(\d+)(?: in blocks of (\d+))?")


def all_readings():
    # The rows in the order of experiment_priority_loops --list-readings (as
    # certify_fixed_order_loops.sh runs them), else by name.
    program = os.environ.get("EXPERIMENT_PRIORITY_LOOPS", os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "build", "bin", "experiment_priority_loops"))
    try:
        return subprocess.run([program, "--list-readings"], capture_output=True, text=True, check=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        return []


class Mixed(Exception):
    """Directories that must not be added up: per-set beside per-start, or shards that are not
    distinct parts of one partition of a set's starts."""


def describe(shard):
    index, count, batch = shard
    return "the whole" if count is None else "shard %d/%d %s" % (
        index, count, "modulo %d" % count if batch == 1 else "in blocks of %d" % batch)


def check_partition(parts):
    """parts: (directory, point set or None, (I, N, B) or (None, None, None) for a whole run).
    Raises Mixed unless each set's directories are distinct shards of one partition; returns,
    per set given in shards, a line saying which shards of how many are there."""
    by_set = collections.defaultdict(list)
    for d, point_set, shard in parts:
        if point_set is not None:
            by_set[point_set].append((d, shard))
    for point_set, runs in by_set.items():
        (d0, first), rest = runs[0], runs[1:]
        seen = {first[0]: d0}
        for d, shard in rest:
            if first[0] is None or shard[0] is None:
                raise Mixed("%s (%s) and %s (%s) both hold runs of %s" % (d0, describe(first), d, describe(shard),
                                                                       point_set))
            if shard[1:] != first[1:]:
                raise Mixed("%s is %s and %s is %s of %s: other partitions of its starts" % (
                    d0, describe(first), d, describe(shard), point_set))
            if shard[0] in seen:
                raise Mixed("%s and %s are both %s of %s" % (seen[shard[0]], d, describe(shard), point_set))
            seen[shard[0]] = d
    coverage = []
    for point_set, runs in by_set.items():
        _, count, batch = runs[0][1]
        if count is not None:
            coverage.append("%s: %d of %d shards (%s), %s" % (
                point_set, len(runs), count, ", ".join(str(i) for i in sorted(r[1][0] for r in runs)),
                "modulo %d" % count if batch == 1 else "in blocks of %d" % batch))
    return coverage


def collect(dirs):
    """Per reading, the counts summed over dirs (runs, at the limit, loops certified, ended later,
    not settled, stuck); the seconds per reading; in how many dirs each reading is complete; the
    kinds of order seeds seen ({"per-set" or "per-start": the first file of that kind}); and,
    per set given in shards, which shards are there."""
    totals = collections.OrderedDict()
    seconds = collections.Counter()
    complete = collections.Counter()
    kinds = {}  # per-set or per-start: the first file of that kind
    parts = []  # (directory, point set, shard) for check_partition
    for d in dirs:
        shards = {}  # shard -> the first file saying so
        for name in sorted(os.listdir(d)):
            if not name.endswith(".txt") or name == "progress.txt":
                continue
            reading = name[:-4]
            with open(os.path.join(d, name)) as f:
                lines = [line.strip() for line in f]
            found = [m for m in map(LINE.match, lines) if m]
            if not found:
                continue
            m = SHARD.search(lines[0])
            shard = (int(m.group(1)), int(m.group(2)), int(m.group(3) or 1)) if m else (None, None, None)
            shards.setdefault(shard, os.path.join(d, name))
            if len(shards) > 1:
                raise Mixed("%s holds %s" % (d, " and ".join("%s (%s)" % (describe(k), f) for k, f in shards.items())))
            kind = "per-start" if "a priority per start" in lines[0] else "per-set"
            kinds.setdefault(kind, os.path.join(d, name))
            if len(kinds) > 1:
                raise Mixed("runs with --order-seeds per-set (%s) and per-start (%s) are other samples; "
                            "summarize them apart" % (kinds["per-set"], kinds["per-start"]))
            runs, limit, certified, stuck = (int(found[-1].group(k + 1)) for k in range(4))
            # Files written before the trace limit have no such line: their runs
            # at the limit that are not certified are counted as not settled.
            later = [m for m in map(LATER.match, lines) if m]
            ended, stuck_later, going = ((int(later[-1].group(k + 1)) for k in range(3)) if later
                                         else (0, 0, limit - certified))
            row = totals.setdefault(reading, [0] * 6)
            for k, value in enumerate((runs, limit, certified, ended + stuck_later, going, stuck)):
                row[k] += value
            complete[reading] += 1
        progress = os.path.join(d, "progress.txt")
        point_set = None  # not known without progress.txt: not checked
        if os.path.exists(progress):
            with open(progress) as f:
                for line in f:
                    m = TIME.match(line.strip())
                    if m:
                        seconds[m.group(1)] += int(m.group(2))
                    m = POINT_SET.match(line)
                    if m and point_set is None:
                        point_set = m.group(1)
        if shards:
            parts.append((d, point_set, next(iter(shards))))
    coverage = check_partition(parts)
    return totals, seconds, complete, kinds, coverage


def main(dirs):
    try:
        totals, seconds, complete, kinds, coverage = collect(dirs)
    except Mixed as e:
        sys.stderr.write("summarize_certified_loops.py: %s\n" % e)
        return 2
    print("| reading | runs | still swapping at cycle 200 | loops certified | ended later | not settled | stuck "
          "| seconds |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    uncertified = 0
    order = {r: k for k, r in enumerate(all_readings())}
    for reading in sorted(totals, key=lambda r: (order.get(r, len(order)), r)):
        if complete[reading] != len(dirs):
            continue
        runs, limit, certified, ended, going, stuck = totals[reading]
        uncertified += limit - certified - ended
        print(f"| `{reading}` | {runs:,} | {limit:,} | {certified:,} | {ended:,} | {going:,} | {stuck:,} | "
              f"{seconds[reading]:,} |")
    done = [r for r in totals if complete[r] == len(dirs)]
    print()
    print(f"readings complete: {len(done)}; {sum(totals[r][0] for r in done):,} runs, "
          f"{sum(totals[r][1] for r in done):,} at the limit, {sum(totals[r][2] for r in done):,} certified loops, "
          f"{sum(seconds[r] for r in done):,} s")
    if "per-start" in kinds:
        print("a fixed priority per start (--order-seeds per-start)")
    for line in coverage:
        print(line)
    missing = [r for r in totals if complete[r] != len(dirs)]
    if missing:
        print("not complete in every directory: " + ", ".join(missing))
    return 1 if uncertified else 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.stderr.write("usage: summarize_certified_loops.py OUTDIR [OUTDIR ...]\n")
        sys.exit(2)
    missing_dirs = [d for d in sys.argv[1:] if not os.path.isdir(d)]
    if missing_dirs:
        sys.stderr.write("summarize_certified_loops.py: not a directory: " + ", ".join(missing_dirs) + "\n")
        sys.exit(2)
    sys.exit(main(sys.argv[1:]))
