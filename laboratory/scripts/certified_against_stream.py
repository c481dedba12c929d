#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Sets the loops certified on a shard of a stream beside the stream's own
# counts. STREAM files are the output of `edge_swap_lab experiment --stream`
# (only their tally lines are read; FILE.xz is read as xz); DIRs are those of
# certify_fixed_order_loops.sh run on the same starts (the same point set,
# seed and shard, with --stream-batch equal to the stream's batch). Per
# reading it prints the helper's fixed-order (priority) runs and those at the
# cycle limit as the stream tallied them, and the runs, runs at the limit,
# loops certified and runs ending later that the certification found.
#
#   certified_against_stream.py --stream FILE [FILE ...] --certified DIR [DIR ...] [--batches I/N]
#
# --batches I/N counts only the stream's batches numbered I modulo N (the
# first's start divided by the batch): the shard I/N of a whole stream (one run
# without --shard), as certify_fixed_order_loops.sh --shard I/N --stream-batch B
# takes it, so that each shard is set beside the stream as it is certified.
#
# Exit 0 when every reading of the stream is in the DIRs with the same runs
# and runs at the limit, and each run at the limit is a certified loop or was
# seen to end later; 1 when not; 2 on bad input (a file that is not there, not
# JSON, or a stream that did not finish), naming the file and line.

import argparse
import collections
import json
import lzma
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import summarize_certified_loops  # noqa: E402

PACKAGES_READING = "until-destroyed,pass-over,no-swap-no-tag"  # its rows carry no reading name


class Bad(Exception):
    pass


def stream_counts(paths, batches=None):
    """Per reading, [fixed-order helper runs, of them at the cycle limit], summed over the files;
    with batches (I, N), over the batches numbered I modulo N of a whole stream."""
    counts = collections.defaultdict(lambda: [0, 0])
    for path in paths:
        finished = False
        batch = None
        try:
            with (lzma.open(path, "rt") if path.endswith(".xz") else open(path)) as f:
                for number, line in enumerate(f, 1):
                    try:
                        entry = json.loads(line)
                        if batches is not None and "stream" in entry:
                            if entry["stream"]["shard"] != "0/1":
                                raise Bad("%s:%d: --batches takes a whole stream, not its shard %s"
                                          % (path, number, entry["stream"]["shard"]))
                            batch = int(entry["stream"]["batch"])
                        tally = entry.get("tally")
                        if tally is None:
                            continue
                        finished = finished or tally["complete"] is True
                        if batches is not None:
                            if not batch:
                                raise Bad("%s:%d: a tally before the stream's batch size" % (path, number))
                            if int(tally["first"]) // batch % batches[1] != batches[0]:
                                continue
                        for row in tally["rows"]:
                            if row["strategy"] == "helper" and row["order"] == "priority":
                                count = counts[row.get("reading", PACKAGES_READING)]
                                count[0] += int(row["instances"])
                                count[1] += int(row["limit"])
                    except (ValueError, KeyError, TypeError, AttributeError) as e:
                        raise Bad("%s:%d: not a stream's line (%s)" % (path, number, e))
        except OSError as e:
            raise Bad("%s: %s" % (path, e.strerror or e))
        except (lzma.LZMAError, EOFError, UnicodeDecodeError) as e:
            raise Bad("%s: not readable as %s (%s)" % (path, "xz" if path.endswith(".xz") else "text", e))
        if not finished:
            raise Bad("%s: the stream did not finish (no tally with \"complete\": true)" % path)
    if not counts:
        raise Bad("no fixed-order helper runs in " + ", ".join(paths))
    return counts


def shard_of(text):
    """I/N with 0 <= I < N, as (I, N); None for another text."""
    parts = text.split("/")
    if len(parts) != 2 or not all(p.isdigit() and len(p) < 10 for p in parts):
        return None
    i, n = int(parts[0]), int(parts[1])
    return (i, n) if i < n else None


def main(argv):
    parser = argparse.ArgumentParser(description="loops certified on a stream's shard against the stream's counts")
    parser.add_argument("--stream", nargs="+", required=True, metavar="FILE")
    parser.add_argument("--certified", nargs="+", required=True, metavar="DIR")
    parser.add_argument("--batches", metavar="I/N", help="only the batches numbered I modulo N of a whole stream")
    args = parser.parse_args(argv)
    batches = None
    if args.batches is not None:
        batches = shard_of(args.batches)
        if batches is None:
            sys.stderr.write("certified_against_stream.py: --batches %s: not I/N with 0 <= I < N\n" % args.batches)
            return 2
    for d in args.certified:
        if not os.path.isdir(d):
            sys.stderr.write("certified_against_stream.py: not a directory: %s\n" % d)
            return 2
    try:
        stream = stream_counts(args.stream, batches)
        totals, _, complete, _, _ = summarize_certified_loops.collect(args.certified)
    except (Bad, summarize_certified_loops.Mixed) as e:
        sys.stderr.write("certified_against_stream.py: %s\n" % e)
        return 2
    print("| reading | stream: runs | stream: at the limit | certified: runs | at the limit | loops certified "
          "| ended later | same |")
    print("|---|---:|---:|---:|---:|---:|---:|---|")
    good = 0
    for reading in sorted(stream):
        runs, limit = stream[reading]
        if complete[reading] == len(args.certified):
            c_runs, c_limit, loops, later = totals[reading][:4]
            same = c_runs == runs and c_limit == limit and loops + later == limit
            print(f"| `{reading}` | {runs:,} | {limit:,} | {c_runs:,} | {c_limit:,} | {loops:,} | {later:,} | "
                  f"{'yes' if same else 'NO'} |")
        else:
            same = False
            print(f"| `{reading}` | {runs:,} | {limit:,} | - | - | - | - | not certified |")
        good += same
    at_limit = sum(limit for _, limit in stream.values())
    print()
    print(f"{good} of {len(stream)} readings agree; the stream has {at_limit:,} fixed-order runs at the limit")
    return 0 if good == len(stream) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
