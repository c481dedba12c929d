#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Writes the docs' account of set 2's certified per-start shards from the kept
# directories (laboratory/results/random12_per_start_certified/set2_shardI_of16),
# so that adding a shard is: copy its directory in (with /usr/bin/time's file as
# time.txt), run this, rebuild the report.
#
#   write_set2_per_start_certified.py [--check]
#
# It first sets each shard beside the per-start stream's tallies of the same
# blocks (certified_against_stream.py --batches I/16) and stops unless they agree
# and every run at the limit is a certified loop; then it rewrites the section
# "Set 2 with a priority per start" of results/random12_certified_loops.md and
# the sentence on it in conjectures.md. With --check it writes nothing and
# exits 1 when a file would change. EXPERIMENT_PRIORITY_LOOPS is as for
# summarize_certified_loops.py.

import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import results_archive  # noqa: E402
from write_random12all_certified import check_files, ranges, write_files  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
RESULTS = os.path.join(ROOT, "laboratory", "results")
KEPT = results_archive.folder("random12_per_start_certified")
STREAM = os.path.join(results_archive.folder("random12_per_start"), "set2.jsonl.xz")
LOOPS_MD = os.path.join(RESULTS, "random12_certified_loops.md")
CONJECTURES_MD = os.path.join(ROOT, "laboratory", "doc", "conjectures.md")
READING = "until-destroyed,pass-over,no-swap-no-tag"
SHARDS = 16
STREAM_AT_LIMIT = 1154028  # the whole stream's runs at the limit (stream_topcom.md)
# The program each shard ran with: commit c8fe566's, or 3fd5e70's (the checker's volumes in
# Gmpzf and the trace lines written by hand). A shard run with another: add it here.
PROGRAM = {0: "c8fe566", 1: "c8fe566"}
LATER_PROGRAM = "3fd5e70"

ALL_SEEDS = re.compile(r"^all seeds: (\d+) runs, (\d+) still swapping "
                       r"\((\d+) loops certified by the checker\), (\d+) stuck$")
FEWEST = re.compile(r"^fewest swaps in a certified loop: (\d+) "
                    r"\(seed 2, triangulation (\d+), its priority seed (\d+)\)$")
TIME = re.compile(r"^([\d.]+)user [\d.]+system (?:(\d+):)?(\d+):([\d.]+)elapsed")


class Bad(Exception):
    pass


def load(index, folder):
    shard = {"index": index}
    with open(os.path.join(folder, READING + ".txt")) as f:
        for line in f:
            line = line.rstrip("\n")
            if m := ALL_SEEDS.match(line):
                shard["runs"], shard["limit"], shard["loops"], stuck = map(int, m.groups())
                if stuck or shard["loops"] != shard["limit"]:
                    raise Bad("shard %d: a run at the limit that is not a certified loop" % index)
            elif m := FEWEST.match(line):
                shard["fewest"], shard["first"], shard["priority"] = map(int, m.groups())
    with open(os.path.join(folder, "time.txt")) as f:
        m = TIME.match(f.readline())
        if not m:
            raise Bad("shard %d: time.txt is not /usr/bin/time's output" % index)
        shard["user"] = float(m.group(1))
        shard["wall"] = int(m.group(2) or 0) * 3600 + int(m.group(3)) * 60 + float(m.group(4))
    if "limit" not in shard or "fewest" not in shard:
        raise Bad("shard %d: its reading's file is not complete" % index)
    against = subprocess.run([sys.executable, os.path.join(HERE, "certified_against_stream.py"), "--stream", STREAM,
                              "--certified", folder, "--batches", "%d/%d" % (index, SHARDS)],
                             capture_output=True, text=True)
    said = (against.stdout.strip().splitlines() or [""])[-1]
    if against.returncode != 0 or not said.startswith("1 of 1 readings agree"):
        raise Bad("shard %d: not as the stream says: %s%s" % (index, said, against.stderr.strip()))
    return shard


def section(shards, folders):
    summary = subprocess.run([sys.executable, os.path.join(HERE, "summarize_certified_loops.py")] + folders,
                             capture_output=True, text=True, check=True).stdout.strip()
    limit = sum(s["limit"] for s in shards)
    indices = [s["index"] for s in shards]
    later = [s for s in shards if s["index"] not in PROGRAM] or shards  # the range of one program's shards
    out = ["## Set 2 with a priority per start, shards %s of %d\n" % (ranges(indices), SHARDS)]
    out.append("""The same reading with `--order-seeds per-start` on set 2 (seed `order_seed_of_start(2, I)`
for the start `topcom:I`), whose stream left 1,154,028 of the 5,563,240 runs at the limit
(`results/random12_per_start/set2.jsonl.xz`). The shards are that stream's blocks of 4096 starts
numbered I modulo 16, so that `certified_against_stream.py --batches I/16` sets each shard
beside the stream's tallies of the same blocks as it is certified; two at a time, one per core:

```sh
s=0
/usr/bin/time -o OUT/set2_shard${s}_of16.time bash laboratory/scripts/certify_fixed_order_loops.sh OUT/set2_shard${s}_of16 random-integer:12:2 2-2 --shard $s/16 --stream-batch 4096 --hold 0 --order-seeds per-start until-destroyed,pass-over,no-swap-no-tag
laboratory/scripts/certified_against_stream.py --stream laboratory/results/random12_per_start/set2.jsonl.xz --certified OUT/set2_shard${s}_of16 --batches $s/16
```

The directories are kept in `random12_per_start_certified/` (with `/usr/bin/time`'s file as
`time.txt`); this section and the sentence on it in `conjectures.md` are written from them by
`laboratory/scripts/write_set2_per_start_certified.py`, which stops unless each shard
agrees with the stream. **In each shard the runs at the limit are the stream's in number, and
every one of the %s is a loop certified by the checker.** CPU is user seconds of the shard's
processes (the program and TOPCOM, which enumerates the whole set for each shard), wall the
shard's seconds, beside the other lane and, at times, builds and the test suite on the 2
cores. Both vary between shards of one program (shards %s ran with the same program, %s to %s
CPU seconds), and not in step with that load, so they do not compare the two programs; the
alternating measurement in `conjectures.md` ("The checker's volumes in `Gmpzf` ...") does.
""" % (format(limit, ","), ranges([s["index"] for s in later]), format(round(min(s["user"] for s in later)), ","),
       format(round(max(s["user"] for s in later)), ",")))
    out.append("| shard | runs | at the limit | certified loops | fewest swaps (first start, its priority seed) "
               "| CPU s | wall s | program |")
    out.append("|---:|---:|---:|---:|---|---:|---:|---|")
    for s in shards:
        out.append("| %d | %s | %s | %s | %d (`topcom:%d`, %s) | %s | %s | %s |" % (
            s["index"], format(s["runs"], ","), format(s["limit"], ","), format(s["loops"], ","), s["fewest"],
            s["first"], format(s["priority"], ","), format(round(s["user"]), ","), format(round(s["wall"]), ","),
            PROGRAM.get(s["index"], LATER_PROGRAM)))
    out.append("")
    out.append("The shards added up (`summarize_certified_loops.py` on the directories):\n")
    out.append(summary)
    out.append("")
    left = SHARDS - len(shards)
    if left:
        out.append("The other %d shards (%s of the stream's runs at the limit) are left.\n" % (
            left, format(STREAM_AT_LIMIT - limit, ",")))
    return "\n".join(out).rstrip("\n") + "\n", limit


def summed_seconds(body):
    """The seconds of summarize_certified_loops.py's line, in the section."""
    m = re.search(r"^readings complete: 1; .* certified loops, ([\d,]+) s$", body, re.M)
    return int(m.group(1).replace(",", ""))


def main(check):
    found = []
    for name in os.listdir(KEPT):
        if m := re.fullmatch(r"set2_shard(\d+)_of%d" % SHARDS, name):
            found.append((int(m.group(1)), os.path.join(KEPT, name)))
    found.sort()
    try:
        shards = [load(i, folder) for i, folder in found]
    except (Bad, OSError) as e:
        sys.stderr.write("write_set2_per_start_certified.py: %s\n" % e)
        return 1
    body, limit = section(shards, [folder for _, folder in found])
    with open(LOOPS_MD) as f:
        loops_md = f.read()
    title = "## Set 2 with a priority per start"
    following = "## Set 1 under all 36 readings"
    end = loops_md.index(following)
    start = loops_md.find(title)
    new_loops = loops_md[:start if start >= 0 else end] + body + "\n" + loops_md[end:]  # one blank line between
    with open(CONJECTURES_MD) as f:
        conjectures = f.read()
    done = len(shards) == SHARDS and limit == STREAM_AT_LIMIT
    sentence = ("Set 2's per-start runs at the limit (1,154,028) are %s (shards %s of 16 in "
                "blocks of 4096, %s runs at the limit, the stream's counts block for block; "
                "`results/random12_certified_loops.md`)." % (
                    "all certified loops" if done else "certified loops in the shards done so far",
                    ranges([s["index"] for s in shards]), format(limit, ",")))
    new_conjectures, n = re.subn(r"Set 2's per-start runs at the limit \(1,154,028\) "
                                 r"(?:are not all certified yet\.|"
                                 r"are [^(]*\(shards .*?`results/random12_certified_loops\.md`\)\.)",
                                 lambda m: sentence, conjectures)
    runs = sum(s["runs"] for s in shards)
    seconds = summed_seconds(body)
    row = ("| 12 random integer points, set 2, a priority per start, shards %s of 16 (the stream's "
           "counts block for block, `certified_against_stream.py --batches`) | the package's "
           "| %s | %s | %s | 0 | %s s |"
           % (ranges([s["index"] for s in shards]), format(runs, ","), format(limit, ","), format(limit, ","),
              format(seconds, ",")))
    set1_row = r"\| 12 random integer points, set 1, a priority per start, in 6 shards \|" + \
        r"[^\n]*\n"
    set2_row = r"\| 12 random integer points, set 2, a priority per start[^\n]*\n"
    new_conjectures, m = re.subn(r"(%s)(?:%s)?" % (set1_row, set2_row), lambda g: g.group(1) + row + "\n",
                                 new_conjectures)
    statement = ("set 2's %s too" % format(limit, ",") if done else
                 "set 2's in shards %s of 16 so far: %s" % (ranges([s["index"] for s in shards]), format(limit, ",")))
    new_conjectures, k = re.subn(r"set 1's 285,508 too(?:; set 2's[^)]*)?\)",
                                 lambda g: "set 1's 285,508 too; %s)" % statement,
                                 new_conjectures)
    if (n, m, k) != (1, 1, 1):
        sys.stderr.write("write_set2_per_start_certified.py: conjectures.md has the sentence, the table row and the "
                         "statement on set 2 %d, %d and %d times, not once each\n" % (n, m, k))
        return 1
    files = ((LOOPS_MD, new_loops, loops_md), (CONJECTURES_MD, new_conjectures, conjectures))
    if check:
        return check_files(files)
    write_files(files)
    print("%d shards, %s runs at the limit, all certified loops" % (len(shards), format(limit, ",")))
    return 0


if __name__ == "__main__":
    if sys.argv[1:] not in ([], ["--check"]):
        sys.stderr.write("usage: write_set2_per_start_certified.py [--check]\n")
        sys.exit(2)
    sys.exit(main(sys.argv[1:] == ["--check"]))
