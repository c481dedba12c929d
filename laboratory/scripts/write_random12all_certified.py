#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Writes the docs' account of random12all's certified shards from the kept
# directories (laboratory/results/random12all_certified/shardI_of64),
# so that adding a shard is: copy its directory in, run this, rebuild the report.
#
#   write_random12all_certified.py [--check]
#
# It first checks each shard against the stream's kept tallies
# (certified_against_stream.py: "36 of 36 readings agree") and that every run at
# the limit is a certified loop; then it rewrites the last section of
# results/random12_certified_loops.md, and the random12all rows of
# conjectures.md (the certified table's row and the fixed-order statement).
# With --check it writes nothing and exits 1 when a file would change.
# EXPERIMENT_PRIORITY_LOOPS names the program that lists the readings in order
# (build/bin/experiment_priority_loops by default), as for summarize_certified_loops.py.

import collections
import datetime
import os
import re
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_archive  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
RESULTS = os.path.join(ROOT, "laboratory", "results")
KEPT = results_archive.folder("random12all_certified")
LOOPS_MD = os.path.join(RESULTS, "random12_certified_loops.md")
CONJECTURES_MD = os.path.join(ROOT, "laboratory", "doc", "conjectures.md")
SHARDS = 64

COUNTS = re.compile(r"^all seeds: (\d+) runs, (\d+) still swapping \((\d+) loops certified by the checker\), (\d+) stuck$")
FEWEST = re.compile(r"^fewest swaps in a certified loop: (\d+) ")
LADDER = re.compile(r"^loops certified by cycles traced: (.*)$")
DRIVER = re.compile(r"^loops the driver found: (\d+), ")  # one trace a loop, to where the driver found it
PROGRESS = re.compile(r"^.*, ([a-z-]+,[a-z-]+,[a-z-]+(?:,same-cycle)?): (\d+) s, (\S+)$")


def parse_time(text):
    return datetime.datetime.strptime(text, "%Y-%m-%dT%H:%M:%SZ")


def and_list(items):
    items = [str(i) for i in items]
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def ranges(numbers):
    """0 to 14, 16 and 18"""
    numbers = sorted(numbers)
    parts, k = [], 0
    while k < len(numbers):
        j = k
        while j + 1 < len(numbers) and numbers[j + 1] == numbers[j] + 1:
            j += 1
        if j - k >= 2:
            parts.append("%d to %d" % (numbers[k], numbers[j]))
        else:
            parts.extend(str(n) for n in numbers[k:j + 1])
        k = j + 1
    return and_list(parts)


def dates_text(dates):
    """2026-12-03 to 2026-12-05: the UTC days a shard's readings ended on"""
    dates = sorted(set(dates))
    return dates[0].isoformat() if len(dates) == 1 else "%s to %s" % (dates[0].isoformat(), dates[-1].isoformat())


class Disagree(Exception):
    """A kept shard that is not the stream's in its counts, or has a run at the limit not certified."""


class Shard:
    def __init__(self, index, path):
        self.index, self.path = index, path
        self.readings = {}  # reading -> (runs, limit, certified, stuck, fewest or None)
        self.ladder = collections.Counter()
        self.seconds, self.times = 0, []
        self.streamed = False
        self.driver_traced = 0  # readings whose loops were traced once, to where the driver found them
        for name in os.listdir(path):
            if not name.endswith(".txt") or name == "progress.txt":
                continue
            with open(os.path.join(path, name)) as f:
                lines = [line.rstrip("\n") for line in f]
            counts = [m for m in map(COUNTS.match, lines) if m]
            assert counts, "%s/%s is not complete" % (path, name)
            fewest = [int(m.group(1)) for m in map(FEWEST.match, lines) if m]
            self.readings[name[:-4]] = tuple(int(g) for g in counts[-1].groups()) + (min(fewest) if fewest else None,)
            self.streamed = self.streamed or "triangulations streamed" in lines[0]
            self.driver_traced += any(DRIVER.match(line) for line in lines)
            for m in map(LADDER.match, lines):
                if m:
                    for item in m.group(1).split(", "):
                        cycles, loops = item.split(": ")
                        self.ladder[int(cycles)] += int(loops)
        with open(os.path.join(path, "progress.txt")) as f:
            for line in f:
                m = PROGRESS.match(line.strip())
                if m:
                    self.seconds += int(m.group(2))
                    self.times.append(parse_time(m.group(3)))
        assert len({r[0] for r in self.readings.values()}) == 1, path  # each reading runs every start
        self.starts = next(iter(self.readings.values()))[0]
        self.limit = sum(r[1] for r in self.readings.values())
        self.certified = sum(r[2] for r in self.readings.values())
        self.dates = sorted({t.date() for t in self.times})


    def pipeline(self):
        """How the shard ran: its starts streamed, held, or held with one trace a loop."""
        if self.streamed:
            return "streamed"
        if self.driver_traced == 0:
            return "held"
        return "one trace a loop" if self.driver_traced == len(self.readings) else "held, then one trace a loop"


def load_shards():
    shards = []
    for name in os.listdir(KEPT):
        m = re.fullmatch(r"shard(\d+)_of%d" % SHARDS, name)
        if m:
            shards.append(Shard(int(m.group(1)), os.path.join(KEPT, name)))
    return sorted(shards, key=lambda s: s.index)


def check_against_streams(shards):
    for s in shards:
        result = subprocess.run(
            [sys.executable, os.path.join(HERE, "certified_against_stream.py"), "--stream",
             os.path.join(results_archive.folder("random12all"), "shard_%d.jsonl.xz" % s.index), "--certified", s.path],
            capture_output=True, text=True)
        said = (result.stdout.strip().splitlines() or [""])[-1] + result.stderr.strip()
        if result.returncode != 0 or "36 of 36 readings agree" not in said:
            raise Disagree("shard %d: %s" % (s.index, said))
        if len(s.readings) != 36 or s.limit != s.certified:
            raise Disagree("shard %d: %d readings, %d runs at the limit, %d certified loops" % (
                s.index, len(s.readings), s.limit, s.certified))


def summary_table(shards):
    result = subprocess.run([sys.executable, os.path.join(HERE, "summarize_certified_loops.py")] +
                            [s.path for s in shards], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    # The directories' paths are the kept ones; print them relative to the results folder.
    return result.stdout.strip()


def fewest_rows(shards, readings):
    rows = []
    for reading in readings:
        per_shard = {s.index: s.readings[reading][4] for s in shards if s.readings[reading][4] is not None}
        values = collections.Counter(per_shard.values())
        parts = []
        for value in sorted(values):
            which = sorted(k for k, v in per_shard.items() if v == value)
            parts.append("%d in %s" % (value, "shard " + str(which[0]) if len(which) == 1 else
                                       "shards " + ranges(which) if len(which) <= 4 else "%d shards" % len(which)))
        loops = sum(s.readings[reading][2] for s in shards)
        rows.append((reading, loops, min(per_shard.values()), "; ".join(parts), len(values) > 1))
    return rows


def section(shards, readings):
    indices = [s.index for s in shards]
    starts = sum(s.starts for s in shards)
    limit = sum(s.limit for s in shards)
    runs = 36 * starts
    all_dates = sorted({d for s in shards for d in s.dates})
    ladder = collections.Counter()
    for s in shards:
        ladder.update(s.ladder)
    rows = fewest_rows(shards, readings)
    by_fewest = collections.Counter(r[2] for r in rows)
    differ = [r for r in rows if r[4]]
    left = SHARDS - len(shards)
    # The estimate for the shards left: the current pipeline's shards only (one trace a loop).
    current = [s for s in shards if s.pipeline() == "one trace a loop"]
    median = statistics.median(s.seconds for s in current)
    out = []
    out.append("## Set 1 under all 36 readings, random12all's shards\n")
    out.append("""random12all (`random12all_shards.md`) runs every fine triangulation of set 1 under all 36
readings in seed 1's fixed order, in 64 shards of blocks of 4096 starts (`edge_swap_lab experiment
--stream`, the block numbered K in shard K modulo 64). The sections above certify the
package's reading only. Here a shard of that stream is certified under every reading:
`experiment_priority_loops --stream-batch 4096 --shard I/64` takes the same starts as the
stream's shard I, and `certified_against_stream.py` sets the certified counts beside the
stream's kept tallies reading by reading.

```sh
s=0
bash laboratory/scripts/certify_fixed_order_loops.sh OUT/shard${s}_of64 random-integer:12:1 1-1 --shard $s/64 --stream-batch 4096
laboratory/scripts/summarize_certified_loops.py OUT/shard${s}_of64
laboratory/scripts/certified_against_stream.py --stream laboratory/results/random12all/shard_$s.jsonl.xz --certified OUT/shard${s}_of64
```

The output directories are kept in `random12all_certified/`; this section and the random12all
rows of `conjectures.md` are written from them by
`laboratory/scripts/write_random12all_certified.py`, which first runs
`certified_against_stream.py` on each shard and stops unless all 36 readings agree. The
pipeline column says how each shard ran: "streamed", with `--hold 0`, one process and one
TOPCOM enumeration a reading; "held", the shard's starts held and the 36 readings run in one
process on one enumeration (the files are the same but for the first line, which gives the
number of triangulations where it said "streamed"); "one trace a loop", each loop traced once,
to where the helper's driver found its state first come back, not on a ladder of longer and
longer traces (the same counts, with 1.6 to 1.9 times less CPU time where measured,
`conjectures.md`; a reading's file says how its loops were traced in a line of its own).
Shards 33 and later ran with the program of commit 3fd5e70 (shard 34 from its seventh reading
on), whose checker computes exact volumes in `Gmpzf` and whose trace lines are written by hand: the same
files, 17% less CPU time where measured (`conjectures.md`).
""")
    out.append("**Shards %s (%s starts: shard I is the blocks of 4096 numbered I modulo 64):**\n"
               "under each of the 36 readings, in each shard, the runs at the limit are the stream's in\n"
               "number, and **every one of the %s fixed-order runs at the limit is a certified loop**\n"
               "(`certified_against_stream.py` on each shard: \"36 of 36 readings agree\", exit 0). Times are\n"
               "wall seconds of one process on one core of this 2-core machine, beside one or two other jobs\n"
               "(shards 15 and 17 also beside builds: 5,904 and 5,063 s beside a whole build of the tests,\n"
               "five jobs on the two cores at times; a shard stopped and resumed enumerates its starts again).\n"
               "Shards 15 and 17 ran twice, with the same counts: the folders of their first runs did not\n"
               "outlast the machine they ran on.\n"
               % (ranges(indices), format(starts, ","), format(limit, ",")))
    out.append("| shard | fixed-order runs at the limit (36 readings) | certified loops | seconds | pipeline | run on (UTC) |")
    out.append("|---:|---:|---:|---:|---|---|")
    for s in shards:
        out.append("| %d | %s | %s | %s | %s | %s |" % (s.index, format(s.limit, ","), format(s.certified, ","),
                                                           format(s.seconds, ","), s.pipeline(),
                                                           dates_text(s.dates)))
    out.append("")
    out.append("The traces that certified the loops, by length: %s. The first pipelines traced a run at the "
               "limit on a ladder of 4, 16, 32, 64, ... cycles until a trace certified its loop; the current one "
               "traces it once, to where the driver found its state come back, and counted at the first of "
               "those lengths that is not shorter (`conjectures.md`, \"How the program keeps this cheap\")." % and_list(
        ["%d cycles for %s" % (c, format(n, ",")) for c, n in sorted(ladder.items()) if n]))
    out.append("The fewest swaps in a loop over the shards: %s. Per reading, with the fewest in each shard "
               "(a reading with few loops in a shard can have only long ones there; %d readings differ "
               "from shard to shard):\n" % (
                   and_list(["%d under %d readings" % (v, n) for v, n in sorted(by_fewest.items())]), len(differ)))
    out.append("| reading | certified loops | fewest swaps | fewest in each shard |")
    out.append("|---|---:|---:|---|")
    for reading, loops, fewest, parts, _ in rows:
        out.append("| `%s` | %s | %d | %s |" % (reading, format(loops, ","), fewest, parts))
    out.append("")
    out.append("The shards added up (`summarize_certified_loops.py` on the directories):\n")
    out.append(summary_table(shards))
    out.append("")
    if left:
        out.append("The stream's other %d shards are left. At the median time of the %d shards run by the "
                   "current pipeline (one trace a loop; %s s, shards %s, beside other jobs), that is about %d core-hours; to spread "
                   "them, a Slurm array (`s=${SLURM_ARRAY_TASK_ID}` in the commands above).\n" % (
                       left, len(current), format(int(median), ","), ranges([s.index for s in current]),
                       round(left * median / 3600)))
    else:
        out.append("All %d shards of the stream are certified: every fine triangulation of set 1 (%s), under "
                   "each of the 36 readings. Their times add up to %d core-hours, on the pipelines of the table and beside "
                   "other jobs; the %d shards of the current pipeline took %s s at the median (shards %s).\n" % (
                       SHARDS, format(starts, ","), round(sum(s.seconds for s in shards) / 3600), len(current),
                       format(int(median), ","), ranges([s.index for s in current])))
    return "\n".join(out), runs, limit, all_dates, starts


def check_files(files):
    """files: (path, new text, text now). Says which would change; 1 if any would."""
    changed = [path for path, new, now in files if new != now]
    for path in changed:
        print("would change " + os.path.relpath(path, ROOT))
    return 1 if changed else 0


def write_files(files):
    """files: (path, new text, text now). Writes those that change."""
    for path, new, now in files:
        if new != now:
            with open(path, "w") as f:
                f.write(new)
            print("wrote " + os.path.relpath(path, ROOT))


def replace_once(text, pattern, replacement, what):
    new, n = re.subn(pattern, lambda m: replacement, text, flags=re.S)
    assert n == 1, "%s: %d matches" % (what, n)
    return new


def main(check):
    shards = load_shards()
    readings = subprocess.run(
        [os.environ.get("EXPERIMENT_PRIORITY_LOOPS", os.path.join(ROOT, "build", "bin", "experiment_priority_loops")),
         "--list-readings"], capture_output=True, text=True, check=True).stdout.split()
    assert len(readings) == 36
    try:
        check_against_streams(shards)
    except Disagree as e:
        sys.stderr.write("write_random12all_certified.py: %s\n" % e)
        return 1
    body, runs, limit, dates, starts = section(shards, readings)
    indices = ranges(s.index for s in shards)
    seconds = sum(s.seconds for s in shards)
    with open(LOOPS_MD) as f:
        loops_md = f.read()
    head = loops_md[:loops_md.index("## Set 1 under all 36 readings")]
    head = replace_once(head, r"^# Fixed-order runs at the limit on 12 random integer points, certified(?: \([^)]*\))?",
                        "# Fixed-order runs at the limit on 12 random integer points, certified", "title")
    new_loops = head + body
    with open(CONJECTURES_MD) as f:
        conjectures = f.read()
    new_conjectures = replace_once(
        conjectures, r"\| 12 random integer points, set 1, random12all's shards [^|]*\| all 36 \|[^\n]*",
        "| 12 random integer points, set 1, random12all's shards %s of 64 (run %s; the stream's counts reading by "
        "reading, `certified_against_stream.py`) | all 36 | %s | %s | %s | 0 | %s s |" % (
            indices, dates_text(dates), format(runs, ","), format(limit, ","), format(limit, ","),
            format(seconds, ",")), "certified table row")
    fewest = collections.Counter(r[2] for r in fewest_rows(shards, readings))
    small, rest = min(fewest), sorted(v for v in fewest if v != min(fewest))
    new_conjectures = replace_once(
        new_conjectures, r"and under all 36 readings on random12all's shards .*?`results/random12_certified_loops.md`\)",
        "and under all 36 readings on random12all's shards %s of 64 (%s of set 1; %s runs at the limit, all "
        "loops, the stream's counts reading by reading; the fewest of %d swaps under %d readings, %d to %d under the "
        "others; `results/random12_certified_loops.md`)" % (
            indices, ("all %s starts" if len(shards) == SHARDS else "%s starts") % format(starts, ","),
            format(limit, ","), small, fewest[small], rest[0],
            rest[-1]), "fixed-order statement")
    if check:
        return check_files(((LOOPS_MD, new_loops, loops_md), (CONJECTURES_MD, new_conjectures, conjectures)))
    write_files(((LOOPS_MD, new_loops, loops_md), (CONJECTURES_MD, new_conjectures, conjectures)))
    print("%d shards (%s), %s runs, %s at the limit, all certified loops, %s s" % (
        len(shards), indices, format(runs, ","), format(limit, ","), format(seconds, ",")))
    return 0


if __name__ == "__main__":
    if sys.argv[1:] not in ([], ["--check"]):
        sys.stderr.write("usage: write_random12all_certified.py [--check]\n")
        sys.exit(2)
    sys.exit(main(sys.argv[1:] == ["--check"]))
