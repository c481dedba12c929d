#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Streams the JSON lines of `edge_swap experiment` (any number of files, for
# example one per shard; line by line, so tens of millions of lines fit in
# memory) and prints a Markdown table: per family, strategy, behaviour of
# Algorithm 4 and face order, the runs, those whose last state is CGAL's
# Delaunay triangulation (the runs that ended there, and any at the cycle limit
# that were on it then but still swapping, as never-cleared's help swaps can
# be), those stuck, and those still going at the cycle limit, by number of
# points. Files of `experiment --stream` are read by their tallies.
#
# A behaviour joins the readings that differ only in the ending rule or in
# pass-over / facet-cells (conjectures.md: they made the same runs). The
# script checks that claim on the data: each member reading of a row must
# have the same counts, else it says which row differs.
#
#   summarize_readings.py RESULTS.jsonl [MORE.jsonl ...]

import collections
import json
import sys

DEFAULT = "until-destroyed,pass-over,no-swap-no-tag"


def behaviour(reading):
    parts = reading.split(",")
    made = parts[3] if len(parts) > 3 else "next-cycle"
    condition = "any-tetrahedron" if parts[1] == "any-tetrahedron" else "pass-over / facet-cells"
    return (parts[0], condition, made)


def main(paths):
    rows = collections.defaultdict(collections.Counter)
    members = collections.defaultdict(lambda: collections.defaultdict(collections.Counter))
    sizes = set()
    total = 0
    def count(family, strategy, reading, order, n, runs, equal, stuck, limit):
        nonlocal total
        if strategy == "helper":
            key = (family, "helper") + behaviour(reading) + (order,)
        else:
            reading = "-"
            key = (family, strategy, "-", "-", "-", order)
        sizes.add(n)
        for counter in (rows[key], members[key][reading]):
            counter["runs"] += runs
            counter["equal"] += equal
            counter["stuck"] += stuck
            counter["limit"] += limit
            counter["limit %d" % n] += limit
            counter["runs %d" % n] += runs
        total += runs

    for path in paths:
        streamed = False
        with open(path, encoding="utf-8") as f:
            for line in f:
                if not line.strip():
                    continue
                j = json.loads(line)
                if "stream" in j:
                    streamed = True
                elif "tally" in j:
                    t = j["tally"]
                    for r in t["rows"]:
                        count(t["set"].split("|")[0], r["strategy"], r.get("reading", DEFAULT), r["order"],
                              t["points"], r["instances"], r["equal"], r["stuck"], r["limit"])
                elif not streamed:  # a streamed file's run lines are in its tallies
                    count(j["family"], j["strategy"], j.get("reading", DEFAULT), j["order"], j["points"], 1,
                          j["equal_to_cgal"], j["ending"] == "stuck", j["ending"] == "cycle limit reached")
    sizes = sorted(sizes)
    print("| family | strategy | tag lifetime | swap condition | made facets | order | runs | on CGAL's at the end | stuck "
          "| at the cycle limit, by points (%s) |" % ", ".join(map(str, sizes)))
    print("|---|---|---|---|---|---|---:|---:|---:|---|")
    disagreements = []
    for key in sorted(rows):
        r = rows[key]
        by_size = "; ".join("%d of %d" % (r["limit %d" % n], r["runs %d" % n]) for n in sizes if r["runs %d" % n])
        print("| %s | %s | %s | %s | %s | %s | %d | %d | %d | %s |" % (key + (r["runs"], r["equal"], r["stuck"], by_size)))
        counts = {tuple(sorted(c.items())) for c in members[key].values()}
        if len(counts) > 1:
            disagreements.append(key)
    print("\n%d instances in %d files" % (total, len(paths)))
    if disagreements:
        print("readings joined in a row that differ: %s" % disagreements)
    else:
        print("in every row, the readings joined had the same counts")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: summarize_readings.py RESULTS.jsonl [MORE.jsonl ...]")
    main(sys.argv[1:])
