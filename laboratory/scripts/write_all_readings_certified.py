#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Keeps the tasks of stream_and_certify_shard.sh run on set S of the 12 random
# integer points (64 shards: every reading and order streamed, every fixed-order
# run at the limit certified) and writes the docs' account of them.
#
#   write_all_readings_certified.py S [--check]
#   write_all_readings_certified.py S --add OUTDIR [OUTDIR ...]
#
# The kept shards are laboratory/results/random12_setS_all_readings/shardI_of64,
# each the task's stream.jsonl.xz (first line and tallies), stream.log, against.md
# and certified/ (not the whole stream.jsonl). --add copies a finished task's OUTDIR
# there, after checking that it is shard I of 64 of set S and that its against.md
# says all 36 readings agree.
# Without --add: each kept shard is first set beside its stream again
# (certified_against_stream.py: "36 of 36 readings agree", every run at the limit a
# certified loop); then results/random12_setS_all_readings.md is rewritten, and in
# conjectures.md the set's row of the certified table and its phrases in the
# fixed-order statement and in the instance count. With --check it writes nothing
# and exits 1 when a file would change. Exit 2 on bad arguments or a shard that
# does not agree.
# EXPERIMENT_PRIORITY_LOOPS names the program that lists the readings in order
# (build/bin/experiment_priority_loops by default).

import collections
import json
import lzma
import os
import re
import shutil
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_archive  # noqa: E402
from write_random12all_certified import (  # noqa: E402
    CONJECTURES_MD, HERE, RESULTS, ROOT, Disagree, Shard, and_list, check_files, fewest_rows, ranges,
    replace_once, dates_text, write_files)

SHARDS = 64
RUNS_A_START = 93  # plain swapping in 3 orders, the helper in 90 reading-and-order pairs
# Per start, the runs the first streams of the 12 random points made already (plain swapping
# and the package's reading, each in the 3 orders), for each of these sets.
REPEATED_A_START = 6
RANDOM12_SETS = (2, 3)
INSTANCES_BEFORE_ALL_READINGS = 279968001  # conjectures.md's count before these sets
UNREADABLE = (OSError, ValueError, KeyError, IndexError, TypeError, AttributeError, AssertionError,
              lzma.LZMAError, EOFError)  # a kept or given folder that is not a task's
INSTANCES = re.compile(r" instances in ([0-9.]+) s on 1 threads$")


def usage(message):
    sys.stderr.write("write_all_readings_certified.py: %s\n"
                     "usage: write_all_readings_certified.py S [--check] | S --add OUTDIR [OUTDIR ...]\n" % message)
    return 2


class Task:
    """A kept shard: the certified readings (Shard) and the stream's tallies and time."""

    def __init__(self, index, path):
        self.index, self.path = index, path
        self.certified = Shard(index, os.path.join(path, "certified"))
        self.stream_seconds = 0.0
        with open(os.path.join(path, "stream.log")) as f:
            for line in f:
                m = INSTANCES.search(line.rstrip("\n"))
                if m:
                    self.stream_seconds += float(m.group(1))
        self.starts, self.set_name, self.triangulations, self.shard = stream_facts(
            os.path.join(path, "stream.jsonl.xz"))

    @property
    def seconds(self):
        return self.stream_seconds + self.certified.seconds


def stream_facts(path):
    """(starts in the shard, the set's name, its triangulations, I/N) from a stream's tallies."""
    starts, set_name, triangulations, shard = 0, None, None, None
    with lzma.open(path, "rt") as f:
        for line in f:
            entry = json.loads(line)
            if "stream" in entry:
                shard = entry["stream"]["shard"]
            tally = entry.get("tally")
            if tally is not None:
                starts += int(tally["count"])
                if tally["complete"] is True:
                    set_name, triangulations = tally["set"], int(tally["triangulations"])
    return starts, set_name, triangulations, shard


def shards_text(indices):
    """shard 3, or shards 0 to 7"""
    return ("shard %s" if len(indices) == 1 else "shards %s") % ranges(indices)


def starts_words(starts, total, whose):
    """all 1,298,487 starts, or 20,480 of its 1,298,487 starts (whose: "its" or "the")"""
    if starts == total:
        return "all %s starts" % format(total, ",")
    return "%s of %s %s starts" % (format(starts, ","), whose, format(total, ","))


def dates_words(dates):
    return "run " + dates_text(dates)


def fewest_text(by_fewest):
    """4 under 24 readings and 6 under 12 readings"""
    return and_list(["%d under %d readings" % (v, n) for v, n in sorted(by_fewest.items())])


def kept_dir(set_number):
    return results_archive.folder("random12_set%d_all_readings" % set_number)


def add(set_number, outdirs):
    """Copies finished tasks into the kept folder; 2 when one is not shard I/64 of the set or does not agree."""
    want = "random-integer|12|%d" % set_number
    for out in outdirs:
        try:
            with open(os.path.join(out, "against.md")) as f:
                said = f.read().strip().splitlines()[-1]
            starts, set_name, _, shard = stream_facts(os.path.join(out, "stream.jsonl.xz"))
        except UNREADABLE as e:
            return usage("%s: not a finished task of stream_and_certify_shard.sh (%s)" % (out, e))
        m = re.fullmatch(r"(\d+)/%d" % SHARDS, shard or "")
        if set_name != want or not m:
            return usage("%s: shard %s of %s, not a shard of 64 of %s" % (out, shard, set_name, want))
        if not said.startswith("36 of 36 readings agree"):
            return usage("%s: against.md says '%s'" % (out, said))
        if not os.path.isdir(os.path.join(out, "certified")) or not os.path.isfile(os.path.join(out, "stream.log")):
            return usage("%s: no certified/ or no stream.log" % out)
        target = os.path.join(kept_dir(set_number), "shard%d_of%d" % (int(m.group(1)), SHARDS))
        if os.path.exists(target):
            shutil.rmtree(target)
        os.makedirs(target)
        for name in ("stream.jsonl.xz", "stream.log", "against.md"):
            shutil.copy(os.path.join(out, name), target)
        shutil.copytree(os.path.join(out, "certified"), os.path.join(target, "certified"))
        print("kept %s (%s starts)" % (os.path.relpath(target, ROOT), format(starts, ",")))
    return 0


def load_tasks(set_number):
    tasks = []
    folder = kept_dir(set_number)
    for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        m = re.fullmatch(r"shard(\d+)_of%d" % SHARDS, name)
        if m:
            tasks.append(Task(int(m.group(1)), os.path.join(folder, name)))
    return sorted(tasks, key=lambda t: t.index)


def check_tasks(set_number, tasks):
    for t in tasks:
        if t.set_name != "random-integer|12|%d" % set_number or t.shard != "%d/%d" % (t.index, SHARDS):
            raise Disagree("shard %d: its stream is shard %s of %s" % (t.index, t.shard, t.set_name))
        result = subprocess.run(
            [sys.executable, os.path.join(HERE, "certified_against_stream.py"), "--stream",
             os.path.join(t.path, "stream.jsonl.xz"), "--certified", os.path.join(t.path, "certified")],
            capture_output=True, text=True)
        said = (result.stdout.strip().splitlines() or [""])[-1] + result.stderr.strip()
        c = t.certified
        if result.returncode != 0 or "36 of 36 readings agree" not in said:
            raise Disagree("shard %d: %s" % (t.index, said))
        if len(c.readings) != 36 or c.limit != c.certified or c.starts != t.starts:
            raise Disagree("shard %d: %d readings, %d runs at the limit, %d certified loops, %d starts of %d" % (
                t.index, len(c.readings), c.limit, c.certified, c.starts, t.starts))


def run_table(program, paths):
    result = subprocess.run([sys.executable, os.path.join(HERE, program)] + paths, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return result.stdout.strip()


def document(set_number, tasks, readings):
    name = "results/random12_set%d_all_readings.md" % set_number
    indices = [t.index for t in tasks]
    starts = sum(t.starts for t in tasks)
    limit = sum(t.certified.limit for t in tasks)
    seconds = sum(t.seconds for t in tasks)
    dates = sorted({d for t in tasks for d in t.certified.dates})
    rows = fewest_rows([t.certified for t in tasks], readings)
    by_fewest = collections.Counter(r[2] for r in rows)
    total = tasks[0].triangulations
    out = ["# Set %d of the 12 random integer points under every reading and order, certified\n" % set_number]
    out.append("""Every fine triangulation of set %d (TOPCOM, %s, streamed) runs under every reading and order:
plain swapping in the 3 orders and the helper in the 90 pairs of a reading (36) and an order
(storage, random, the fixed priority of seed %d; the 18 `same-cycle` readings have no storage
order), %d runs a start, up to cycle 200. Then every fixed-order run still swapping at cycle 200 is
traced and certified by the independent checker, and the certified counts are set beside the
stream's reading by reading. The set is cut in 64 shards (shard I: the blocks of 4096 starts
numbered I modulo 64), each one task of a job array:

```sh
s=0
bash laboratory/scripts/stream_and_certify_shard.sh OUT/set%d_shard$s random-integer:12:%d $s 64
laboratory/scripts/write_all_readings_certified.py %d --add OUT/set%d_shard$s
```

The second command keeps the task's stream tallies (`stream.jsonl.xz`), its log, `against.md` and
`certified/` in `results/random12_set%d_all_readings/shardI_of64`; this file and the set's
rows of `conjectures.md` are written from them by
`laboratory/scripts/write_all_readings_certified.py %d`, which first sets each kept
shard beside its stream again (`certified_against_stream.py`) and stops unless all 36 readings
agree with every run at the limit a certified loop; ctest `all_readings_certified_docs` runs it
with `--check`.
""" % (set_number, format(total, ","), set_number, RUNS_A_START, set_number, set_number, set_number,
       set_number, set_number, set_number))
    out.append("**%s of 64 (%s, %s runs):** under each of the 36 readings,\n"
               "in each shard, the runs at the limit are the stream's in number, and **every one of the %s\n"
               "fixed-order runs at the limit is a certified loop**. Times are wall seconds of one task on one\n"
               "core of this 2-core machine, two tasks at a time, beside whatever else the machine ran then\n"
               "(builds, tests, doc builds; some days on another machine), so they compare best within\n"
               "one day: the stream's (the times its log gives, TOPCOM's listing included; an attempt cut\n"
               "before its end is not counted) and the certification's (its progress lines).\n" % (
                   shards_text(indices).capitalize(), starts_words(starts, total, "the"),
                   format(RUNS_A_START * starts, ","),
                   format(limit, ",")))
    out.append("| shard | starts | runs | fixed-order runs at the limit (36 readings) | certified loops "
               "| stream s | certification s | run on (UTC) |")
    out.append("|---:|---:|---:|---:|---:|---:|---:|---|")
    for t in tasks:
        c = t.certified
        out.append("| %d | %s | %s | %s | %s | %s | %s | %s |" % (
            t.index, format(t.starts, ","), format(RUNS_A_START * t.starts, ","), format(c.limit, ","),
            format(c.certified, ","), format(round(t.stream_seconds), ","), format(c.seconds, ","),
            dates_text(c.dates)))
    out.append("")
    out.append("In all %s runs in %s s on one core (%s runs and %s certified loops a core-hour)." % (
        format(RUNS_A_START * starts, ","), format(round(seconds), ","),
        format(round(RUNS_A_START * starts * 3600 / seconds), ","), format(round(limit * 3600 / seconds), ",")))
    out.append("The fewest swaps in a loop over the shards: %s. Per reading, with the fewest in each shard:\n" %
               fewest_text(by_fewest))
    out.append("| reading | certified loops | fewest swaps | fewest in each shard |")
    out.append("|---|---:|---:|---|")
    for reading, loops, fewest, parts, _ in rows:
        out.append("| `%s` | %s | %d | %s |" % (reading, format(loops, ","), fewest, parts))
    out.append("")
    out.append("The streams added up (`summarize_readings.py` on the kept `stream.jsonl.xz`; rows join the "
               "readings that made the same runs, `conjectures.md`):\n")
    out.append(run_table("summarize_readings.py", [os.path.join(t.path, "stream.jsonl.xz") for t in tasks]))
    out.append("")
    out.append("The certifications added up (`summarize_certified_loops.py` on the kept `certified/`):\n")
    out.append(run_table("summarize_certified_loops.py", [os.path.join(t.path, "certified") for t in tasks]))
    out.append("")
    left = SHARDS - len(tasks)
    if left:
        median = statistics.median(t.seconds for t in tasks)
        out.append("The other %d shards are left: at the median time of those above (%s s), about %d core-hours.\n" % (
            left, format(round(median), ","), round(left * median / 3600)))
    else:
        out.append("All 64 shards are certified: every fine triangulation of set %d under each reading and order.\n"
                   % set_number)
    return name, "\n".join(out), dict(indices=indices, starts=starts, limit=limit, seconds=seconds, dates=dates,
                                      total=total, fewest=fewest_text(by_fewest))


def row_pattern(set_number):
    return r"\| 12 random integer points, set %d, under all 36 readings, [^|]*\| all 36 \|[^\n]*" % set_number


def clause_pattern(set_number):
    return r"and under all 36 readings on set %d's shards? .*?`results/random12_set%d_all_readings\.md`\)" % (
        set_number, set_number)


def place(text, pattern, replacement, set_number, joint, what):
    """Replace the set's part of conjectures.md; the first time, put it beside the other set's (2 before 3)."""
    if re.search(pattern(set_number), text, flags=re.S):
        return replace_once(text, pattern(set_number), replacement, what)
    other = 5 - set_number
    beside = list(re.finditer(pattern(other), text, flags=re.S))
    if len(beside) != 1:
        raise Disagree("conjectures.md has neither %s nor set %d's to put it beside" % (what, other))
    m = beside[0]
    if set_number < other:
        return text[:m.start()] + replacement + joint + text[m.start():]
    return text[:m.end()] + joint + replacement + text[m.end():]


def conjectures_text(text, set_number, facts):
    """The set's row of the certified table and its fixed-order phrase."""
    name, f = "`results/random12_set%d_all_readings.md`" % set_number, facts
    shards = "%s of 64" % shards_text(f["indices"])
    text = place(
        text, row_pattern,
        "| 12 random integer points, set %d, under all 36 readings, %s (%s; one task a shard, "
        "`stream_and_certify_shard.sh`) | all 36 | %s | %s | %s | 0 | %s s |" % (
            set_number, shards, dates_words(f["dates"]), format(36 * f["starts"], ","), format(f["limit"], ","),
            format(f["limit"], ","), format(round(f["seconds"]), ",")),
        set_number, "\n", "set %d's certified row" % set_number)
    return place(
        text, clause_pattern,
        "and under all 36 readings on set %d's %s (%s; %s runs at the limit, all loops, the "
        "stream's counts reading by reading; the fewest swaps in a loop %s; %s)" % (
            set_number, shards, starts_words(f["starts"], f["total"], "its"), format(f["limit"], ","),
            f["fewest"], name),
        set_number, ", ", "set %d's statement" % set_number)


def instance_count(text, loaded):
    """The sentence of conjectures.md that adds the sets' runs to the laboratory's instance count;
    loaded: the kept shards already read, by set."""
    parts, total = [], INSTANCES_BEFORE_ALL_READINGS
    for set_number in RANDOM12_SETS:
        tasks = loaded[set_number] if set_number in loaded else load_tasks(set_number)
        starts = sum(t.starts for t in tasks)
        if starts:
            total += (RUNS_A_START - REPEATED_A_START) * starts
            parts.append("set %d's %s of 64 (%s instances, less the %s that repeat its first stream's)" % (
                set_number, shards_text([t.index for t in tasks]), format(RUNS_A_START * starts, ","),
                format(REPEATED_A_START * starts, ",")))
    return replace_once(
        text, r"Sets 2 and 3 of the 12 random points under every reading add [^\n]*?, for [0-9,]+\.",
        "Sets 2 and 3 of the 12 random points under every reading add %s, for %s." % (
            and_list(parts), format(total, ",")), "the instance count")


def main(argv):
    if not argv or not re.fullmatch(r"[23]", argv[0]):
        return usage("S is 2 or 3 (set 1 is write_random12all_certified.py's), not '%s'" % (argv[:1] or [""])[0])
    set_number, rest = int(argv[0]), argv[1:]
    if rest[:1] == ["--add"]:
        return add(set_number, rest[1:]) if rest[1:] else usage("--add takes the task folders")
    if rest not in ([], ["--check"]):
        return usage("unknown arguments: %s" % " ".join(rest))
    try:
        tasks = load_tasks(set_number)
    except UNREADABLE as e:
        return usage("a kept shard is not a task's folder (%s)" % e)
    if not tasks:
        return usage("no kept shard in %s" % os.path.relpath(kept_dir(set_number), ROOT))
    readings = subprocess.run(
        [os.environ.get("EXPERIMENT_PRIORITY_LOOPS", os.path.join(ROOT, "build", "bin", "experiment_priority_loops")),
         "--list-readings"], capture_output=True, text=True, check=True).stdout.split()
    assert len(readings) == 36
    try:
        check_tasks(set_number, tasks)
    except Disagree as e:
        sys.stderr.write("write_all_readings_certified.py: %s\n" % e)
        return 2
    name, body, facts = document(set_number, tasks, readings)
    path = os.path.join(ROOT, "laboratory", name)
    now = open(path).read() if os.path.exists(path) else None
    with open(CONJECTURES_MD) as f:
        conjectures = f.read()
    try:
        new_conjectures = instance_count(conjectures_text(conjectures, set_number, facts), {set_number: tasks})
    except Disagree as e:
        sys.stderr.write("write_all_readings_certified.py: %s\n" % e)
        return 2
    files = ((path, body + "\n", now), (CONJECTURES_MD, new_conjectures, conjectures))
    if "--check" in rest:
        return check_files(files)
    write_files(files)
    print("set %d: shards %s, %s starts, %s at the limit, all certified loops, %s s" % (
        set_number, ranges(facts["indices"]), format(facts["starts"], ","), format(facts["limit"], ","),
        format(round(facts["seconds"]), ",")))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
