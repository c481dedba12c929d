#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Certifies the fixed-order loops among the cases that `edge_swap_lab experiment
--cases DIR` saved: for starts that are not TOPCOM's (scramble:K, placing),
which experiment_priority_loops cannot enumerate.

Each case in the fixed order (`"order": "priority"`) is replayed with a trace
(`edge_swap_lab replay CASE --max-cycles K --trace T`) on a ladder of cycle limits,
16, 64, 256 and then the trace limit (8 times the case's limit by default),
and the trace is checked by the independent checker (`check_trace`). The
order is fixed, so a loop the checker certifies (a state, cells and tags,
repeated at the end of two rounds) is the run's loop at any limit. A run that
ends within the trace limit is "ended later"; one still going with no state
repeated is "not settled". Cases in storage or random order are counted but
not certified: storage order is the container's, not a function of the state,
so a repeated state does not prove a loop.

One JSON line per case is appended to OUT (a stopped run resumes), then a
table per reading and order is printed. Exit 0 when every fixed-order case is
a certified loop or ended later, 1 when one is not settled or the checker
refused a trace, 2 on bad arguments or an unreadable case (nothing written).

    certify_case_loops.py CASES_DIR OUT.jsonl [--edge-swap-lab BIN] [--check-trace BIN]
                          [--trace-limit N] [--jobs N]
"""

import argparse
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile

LADDER = (16, 64, 256)


def rounds_of(trace_path):
    """Swaps per round, from the trace's round lines."""
    swaps = {}
    with open(trace_path) as f:
        for line in f:
            if '"round"' not in line:
                continue
            d = json.loads(line)
            if "round" in d and "swaps" in d:
                swaps[d["round"]] = d["swaps"]
    return swaps


def certify(case_path, edge_swap, check_trace, trace_limit):
    with open(case_path) as f:
        case = json.load(f)
    result = {"case": os.path.basename(case_path), "order": case.get("order"),
              "reading": case.get("reading", ""), "seed": case.get("seed"), "start": case.get("start")}
    if case.get("order") != "priority":
        result["status"] = "not certifiable (order " + str(case.get("order")) + ")"
        return result
    limit = trace_limit or 8 * case.get("max_cycles", 200)
    with tempfile.TemporaryDirectory() as work:
        trace = os.path.join(work, "trace.jsonl")
        for cycles in [c for c in LADDER if c < limit] + [limit]:
            replay = subprocess.run([edge_swap, "replay", case_path, "--max-cycles", str(cycles), "--trace", trace],
                                    capture_output=True, text=True)
            if replay.returncode not in (0, 1):
                result.update(status="replay failed", error=replay.stderr.strip()[-300:])
                return result
            checked = subprocess.run([check_trace, trace], capture_output=True, text=True)
            try:
                verdict = json.loads(checked.stdout)
            except json.JSONDecodeError:
                verdict = {"confirmed": False, "error": checked.stderr.strip()[-300:]}
            if not verdict.get("confirmed"):
                result.update(status="checker refused", error=verdict.get("error", ""))
                return result
            if verdict.get("loop_certified"):
                a = verdict["loop"]["state_after_round"]
                b = verdict["loop"]["again_after_round"]
                swaps = rounds_of(trace)
                result.update(status="certified", traced_to=cycles, loop_from=a, loop_to=b,
                              loop_swaps=sum(swaps.get(r, 0) for r in range(a + 1, b + 1)))
                return result
            if verdict.get("end") != "cycle limit reached":
                result.update(status="ended later", end=verdict.get("end"), rounds=verdict.get("rounds"),
                              ends_on_delaunay=verdict.get("ends_on_delaunay"))
                return result
        result.update(status="not settled", traced_to=limit)
        return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cases")
    parser.add_argument("out")
    here = os.path.dirname(os.path.abspath(__file__))
    build = os.path.join(here, "..", "..", "build", "bin")
    parser.add_argument("--edge-swap-lab", default=os.path.join(build, "edge_swap_lab"))
    parser.add_argument("--check-trace", default=os.path.join(build, "check_trace"))
    parser.add_argument("--trace-limit", type=int, default=0)
    parser.add_argument("--jobs", type=int, default=1)
    args = parser.parse_args()
    if not os.path.isdir(args.cases):
        print(f"certify_case_loops.py: '{args.cases}' is not a folder of cases", file=sys.stderr)
        return 2
    if not 1 <= args.jobs <= 256 or not 0 <= args.trace_limit <= 1000000000:
        print("certify_case_loops.py: --jobs is from 1 to 256 and --trace-limit from 0 to 1000000000", file=sys.stderr)
        return 2
    for tool in (args.edge_swap_lab, args.check_trace):
        if not os.access(tool, os.X_OK):
            print(f"certify_case_loops.py: '{tool}' is not a program", file=sys.stderr)
            return 2
    names = sorted(n for n in os.listdir(args.cases) if n.endswith(".json"))
    if not names:
        print(f"certify_case_loops.py: no case file (*.json) in '{args.cases}'", file=sys.stderr)
        return 2
    for n in names:  # every case is read before anything is written
        try:
            with open(os.path.join(args.cases, n)) as f:
                case = json.load(f)
            if not isinstance(case, dict) or not isinstance(case.get("order"), str) or "instance" not in case:
                raise ValueError("not a case of edge_swap_lab experiment --cases")
            limit = case.get("max_cycles", 200)  # the trace limit is 8 times it
            if type(limit) is not int or not 1 <= limit <= 125000000:
                raise ValueError(f"max_cycles {limit!r} is not a whole number from 1 to 125000000")
        except (OSError, UnicodeDecodeError, ValueError) as e:
            print(f"certify_case_loops.py: {os.path.join(args.cases, n)}: {e}", file=sys.stderr)
            return 2
    done = {}
    if os.path.exists(args.out):
        with open(args.out) as f:
            for number, line in enumerate(f, 1):
                if not line.strip():
                    continue
                try:
                    d = json.loads(line)
                    done[d["case"]] = d
                except (ValueError, KeyError, TypeError):
                    print(f"certify_case_loops.py: {args.out}, line {number}: not a line of this script", file=sys.stderr)
                    return 2
    todo = [n for n in names if n not in done]
    with open(args.out, "a") as out, concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(certify, os.path.join(args.cases, n), args.edge_swap_lab, args.check_trace,
                               args.trace_limit) for n in todo]
        for future in futures:
            d = future.result()
            done[d["case"]] = d
            out.write(json.dumps(d, sort_keys=True) + "\n")
            out.flush()
    table = {}
    for d in done.values():
        row = table.setdefault((d["reading"], d["order"]), {})
        row[d["status"]] = row.get(d["status"], 0) + 1
        if d["status"] == "certified":
            best = row.get("fewest")
            if best is None or (d["loop_swaps"], d["case"]) < (best["loop_swaps"], best["case"]):
                row["fewest"] = d
    print("| reading | order | cases | certified loops | ended later | not settled | not certifiable | fewest swaps in a turn (rounds; case) |")
    print("|---|---|---:|---:|---:|---:|---:|---|")
    bad = 0
    for (reading, order), row in sorted(table.items()):
        counted = {k: v for k, v in row.items() if k != "fewest"}
        other = sum(v for k, v in counted.items() if k.startswith("not certifiable"))
        bad += sum(v for k, v in counted.items() if k in ("not settled", "checker refused", "replay failed"))
        fewest = row.get("fewest")
        where = (f"{fewest['loop_swaps']} ({fewest['loop_to'] - fewest['loop_from']}; {fewest['case']})"
                 if fewest else "")
        name = reading or "the package's"  # its cases carry no reading
        print(f"| {name} | {order} | {sum(counted.values())} | {counted.get('certified', 0)} | "
              f"{counted.get('ended later', 0)} | {counted.get('not settled', 0)} | {other} | {where} |")
    refused = sum(1 for d in done.values() if d["status"] in ("checker refused", "replay failed"))
    if refused:
        print(f"{refused} cases the checker refused or could not replay (see {args.out})", file=sys.stderr)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
