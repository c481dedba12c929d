#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Streams the JSON lines of `edge_swap_lab experiment` (any number of files, for
# example one per shard; line by line, so tens of millions of lines fit in
# memory) and prints a Markdown table: per family, strategy, behaviour of
# Algorithm 4 and face order, the runs, those whose last state is CGAL's
# Delaunay triangulation (the runs that ended there, and any at the cycle limit
# that were on it then but still swapping, as never-cleared's help swaps can
# be), those stuck, and those still going at the cycle limit, by number of
# points. Files of `experiment --stream` are read by their tallies, so a
# shard's file may be kept as its "stream" and "tally" lines alone, and
# compressed (.xz or .gz: results/random12all/ keeps its shards so). It
# says which shards of each `--shard I/N` are present, refuses one given
# twice, names the streamed files that stopped before their last tally, and
# refuses files run with different --order-seeds (their random-order rows
# are different samples).
#
# A behaviour joins the readings that differ only in the ending rule or in
# pass-over / facet-cells (conjectures.md: they made the same runs). The
# script checks that claim on the data: each member reading of a row must
# have the same counts, else it says which row differs.
#
#   summarize_readings.py RESULTS.jsonl[.xz|.gz] [MORE ...]

import collections
import gzip
import json
import lzma
import sys

DEFAULT = "until-destroyed,pass-over,no-swap-no-tag"


def behaviour(reading):
    parts = reading.split(",")
    made = parts[3] if len(parts) > 3 else "next-cycle"
    condition = "any-tetrahedron" if parts[1] == "any-tetrahedron" else "pass-over / facet-cells"
    return (parts[0], condition, made)


def fail(message):
    sys.stderr.write("summarize_readings.py: %s\n" % message)
    sys.exit(2)


def ranges(numbers):
    """'0-3, 7' for [0, 1, 2, 3, 7]."""
    parts = []
    for k in numbers:
        if parts and parts[-1][1] == k - 1:
            parts[-1][1] = k
        else:
            parts.append([k, k])
    return ", ".join(str(a) if a == b else "%d-%d" % (a, b) for a, b in parts)


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

    shards = collections.defaultdict(dict)  # N -> {I: path}
    order_seeds = {}  # per-set or per-start -> the first file run so
    unfinished = []
    for path in paths:
        streamed = finished = False
        opener = lzma.open if path.endswith(".xz") else gzip.open if path.endswith(".gz") else open
        try:
            with opener(path, "rt", encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    if not line.strip():
                        continue
                    try:
                        j = json.loads(line)
                    except ValueError:
                        fail("%s, line %d: not a JSON line" % (path, number))
                    if "stream" in j:
                        streamed = True
                        order_seeds.setdefault(j["stream"].get("order_seeds", "per-set"), path)
                        shard = j["stream"].get("shard", "")
                        if shard:
                            i, n = map(int, shard.split("/"))
                            if i in shards[n]:
                                fail("shard %s given twice: %s and %s" % (shard, shards[n][i], path))
                            shards[n][i] = path
                    elif "tally" in j:
                        t = j["tally"]
                        finished = finished or t["complete"]
                        for r in t["rows"]:
                            count(t["set"].split("|")[0], r["strategy"], r.get("reading", DEFAULT), r["order"],
                                  t["points"], r["instances"], r["equal"], r["stuck"], r["limit"])
                    elif not streamed:  # a streamed file's run lines are in its tallies
                        if j["start"].startswith("topcom:"):
                            order_seeds.setdefault("per-start" if "order_seed" in j else "per-set", path)
                        count(j["family"], j["strategy"], j.get("reading", DEFAULT), j["order"], j["points"], 1,
                              j["equal_to_cgal"], j["ending"] == "stuck", j["ending"] == "cycle limit reached")
        except (OSError, EOFError, lzma.LZMAError, UnicodeDecodeError) as e:
            fail("%s: %s" % (path, e))
        except (KeyError, TypeError, ValueError) as e:
            fail("%s: not a file of edge_swap_lab experiment (%s)" % (path, e))
        if streamed and not finished:
            unfinished.append(path)
    if len(order_seeds) > 1:
        fail("files run with --order-seeds %s (%s) and %s (%s) cannot be summed" %
             tuple(x for mode in sorted(order_seeds) for x in (mode, order_seeds[mode])))
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
    for n in sorted(shards):
        present = sorted(shards[n])
        print("shards of %d: %d present (%s)%s" % (n, len(present), ranges(present),
                                                   "" if len(present) == n else
                                                   ", missing %s" % ranges(sorted(set(range(n)) - set(present)))))
    if unfinished:
        print("streamed files without their set's last tally (stopped early): %s" % ", ".join(unfinished))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: summarize_readings.py RESULTS.jsonl[.xz|.gz] [MORE ...]")
    main(sys.argv[1:])
