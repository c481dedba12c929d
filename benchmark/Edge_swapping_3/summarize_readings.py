#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Streams the JSON lines of `edge_swap experiment` (any number of files, for
# example one per shard) and prints, per family, strategy, reading and face
# order: runs, runs that ended on CGAL's Delaunay triangulation, runs stuck,
# runs still going at the cycle limit, and from how many start triangulations
# the helper failed. Reads line by line, so files of tens of millions of lines
# fit in memory.
#
#   summarize_readings.py RESULTS.jsonl [MORE.jsonl ...]

import collections
import json
import sys

DEFAULT = "until-destroyed,pass-over,no-swap-no-tag"


def main(paths):
    rows = collections.defaultdict(lambda: [0, 0, 0, 0, set()])
    total = 0
    for path in paths:
        with open(path, encoding="utf-8") as f:
            for line in f:
                if not line.strip():
                    continue
                j = json.loads(line)
                reading = j.get("reading", DEFAULT) if j["strategy"] == "helper" else "-"
                key = (j["family"], j["points"], j["strategy"], reading, j["order"])
                row = rows[key]
                row[0] += 1
                row[1] += j["equal_to_cgal"]
                row[2] += j["ending"] == "stuck"
                row[3] += j["ending"] == "cycle limit reached"
                if j["failure"]:
                    row[4].add((j["seed"], j["start"]))
                total += 1
    print("| family | points | strategy | reading | order | runs | ended on CGAL's | stuck | at the cycle limit | starts that failed |")
    print("|---|---:|---|---|---|---:|---:|---:|---:|---:|")
    for key in sorted(rows):
        r = rows[key]
        print("| %s | %d | %s | `%s` | %s | %d | %d | %d | %d | %d |" % (key + (r[0], r[1], r[2], r[3], len(r[4]))))
    print("\n%d instances in %d files" % (total, len(paths)))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: summarize_readings.py RESULTS.jsonl [MORE.jsonl ...]")
    main(sys.argv[1:])
