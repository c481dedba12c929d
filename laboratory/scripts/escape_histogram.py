#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Pools the JSON lines of experiment_escape_times run from many starts (one
# line per start and seed) into a histogram: one line per (ending, cycle,
# whether the end is CGAL's triangulation) with the number of runs, which
# laboratory/doc/plot_escape_times.py plots like the runs themselves.
# Standard error gets the counts: runs, starts, endings, the runs not ended
# by a few cycle counts, and the starts whose slowest run was slowest.
#
#   escape_histogram.py ESCAPE.jsonl [MORE ...] > HISTOGRAM.jsonl

import collections
import json
import sys


def fail(message):
    sys.stderr.write("escape_histogram.py: %s\n" % message)
    sys.exit(2)


def main(paths):
    bins = collections.Counter()
    slowest = collections.defaultdict(int)
    seeds = collections.defaultdict(int)
    for path in paths:
        try:
            with open(path, encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    try:
                        j = json.loads(line)
                        key = (j["ending"], int(j["cycles"]), bool(j["equal_to_cgal"]))
                        source = j["source"]
                    except (ValueError, KeyError, TypeError):
                        fail("%s, line %d: not a line of experiment_escape_times" % (path, number))
                    bins[key] += 1
                    slowest[source] = max(slowest[source], key[1])
                    seeds[source] += 1
        except OSError as e:
            fail(str(e))
    if not bins:
        fail("no runs in %s" % ", ".join(paths))
    for (ending, cycles, equal), runs in sorted(bins.items()):
        print(json.dumps({"ending": ending, "cycles": cycles, "equal_to_cgal": equal, "runs": runs}))
    total = sum(bins.values())
    endings = collections.Counter()
    for (ending, _, equal), runs in bins.items():
        endings["%s%s" % (ending, " on CGAL's" if equal else "")] += runs
    log = sys.stderr
    log.write("%d runs from %d starts (%d to %d seeds each): %s\n" %
              (total, len(seeds), min(seeds.values()), max(seeds.values()),
               ", ".join("%s %d" % kv for kv in sorted(endings.items()))))
    for t in (10, 100, 200, 500, 1000, 2000, 5000, 10000):
        left = sum(runs for (ending, cycles, _), runs in bins.items() if ending != "converged" or cycles > t)
        log.write("  not ended by cycle %d: %d\n" % (t, left))
    for source, cycles in sorted(slowest.items(), key=lambda kv: -kv[1])[:3]:
        log.write("  slowest run %d cycles from %s\n" % (cycles, source))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: escape_histogram.py ESCAPE.jsonl [MORE ...] > HISTOGRAM.jsonl")
    main(sys.argv[1:])
