#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Streamed TOPCOM runs in shards, kept as their tally lines alone (compressed),
# add up to the whole run in summarize_readings.py; the script names missing
# shards and unfinished files, and refuses a shard given twice and bad files.
# The shards kept in laboratory/results/random12all/ add up to the
# table of results/random12all_shards.md, and the kept set 3 of the 12 random
# points, and its three sets run with a priority per start, give their tables
# in results/stream_topcom.md.
#
#   streamed_shards.sh EDGE_SWAP_LAB SOURCE_DIR WORK_DIR
set -euo pipefail
edge_swap=$1 src=$2 work=$3
summarize="python3 $src/laboratory/scripts/summarize_readings.py"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
table() { awk '/^\|/ { print; seen = 1; next } seen { exit }' "$1"; } # the first table

run() { # OUT [--shard I/N]
  local out=$1
  shift
  "$edge_swap" experiment -o "$out" --starts topcom --stream --stream-batch 4 --max-cycles 50 --threads 1 \
    --strategies plain,helper --orders storage,random,priority --families random-integer --sizes 7 --seeds 1 \
    --readings all "$@" > /dev/null 2>&1
}
keep_tallies() { # IN OUT.xz: the stream and tally lines alone, compressed
  python3 -c 'import lzma, sys
with open(sys.argv[1]) as f, lzma.open(sys.argv[2], "wt") as out:
    out.writelines(l for l in f if l.startswith(("{\"stream\"", "{\"tally\"")))' "$1" "$2"
}

run whole.jsonl
$summarize whole.jsonl > whole.txt
for i in 0 1 2; do
  run part$i.jsonl --shard $i/3
  keep_tallies part$i.jsonl part$i.jsonl.xz
done
$summarize part0.jsonl.xz part1.jsonl.xz part2.jsonl.xz > shards.txt
[ "$(table whole.txt | wc -l)" -gt 20 ] || fail "the whole run's table is too short"
diff <(table whole.txt) <(table shards.txt) || fail "the 3 shards' tallies do not add up to the whole run"
grep -q '^shards of 3: 3 present (0-2)$' shards.txt || fail "the 3 shards are not all named present"
grep -q 'stopped early' shards.txt && fail "a finished shard is called unfinished"

$summarize part0.jsonl.xz part2.jsonl.xz > two.txt
grep -q '^shards of 3: 2 present (0, 2), missing 1$' two.txt || fail "a missing shard is not named"

# A shard cut before its last tally: named as stopped early.
python3 -c 'import lzma, sys
lines = lzma.open(sys.argv[1], "rt").readlines()
with open(sys.argv[2], "w") as out:
    out.writelines(lines[:-1])' part1.jsonl.xz cut.jsonl
$summarize part0.jsonl.xz cut.jsonl part2.jsonl.xz > cut.txt
grep -q 'stopped early.*cut.jsonl' cut.txt || fail "a shard without its last tally is not named"

refuses() { # WHAT FILES...: exit 2 and a message naming the problem
  local what=$1
  shift
  set +e
  $summarize "$@" > out.txt 2> err.txt
  local rc=$?
  set -e
  [ $rc -eq 2 ] || fail "$what: exit $rc, not 2"
  [ -s err.txt ] || fail "$what: no message"
  [ -s out.txt ] && fail "$what: a table was printed"
  return 0
}
refuses "a shard given twice" part0.jsonl.xz part0.jsonl.xz
grep -q 'given twice' err.txt || fail "the shard given twice is not named"
echo 'not json' > bad.jsonl
refuses "a line that is not JSON" bad.jsonl
grep -q 'bad.jsonl, line 1' err.txt || fail "the bad line is not named"
echo '{"tally":{"set":"x"}}' > tally.jsonl
refuses "a tally without its fields" tally.jsonl
head -c 200 part0.jsonl.xz > truncated.jsonl.xz
refuses "a truncated compressed file" truncated.jsonl.xz
refuses "a missing file" missing.jsonl
# Files run with a seed per start are other samples of the random orders: not summed with per-set ones.
run per_start.jsonl --shard 1/3 --order-seeds per-start
refuses "shards run with different --order-seeds" part0.jsonl.xz per_start.jsonl part2.jsonl.xz
grep -q 'order-seeds per-set (part0.jsonl.xz) and per-start (per_start.jsonl)' err.txt ||
  fail "the files run with different order seeds are not named"
$summarize per_start.jsonl > per_start.txt || fail "a per-start file alone is refused"

# The kept shards of the 12 random points under all readings add up to the
# table that the report shows.
unpacked=${EDGE_SWAP_LAB_UNPACKED:-$src/laboratory/results}
kept=("$unpacked"/random12all/shard_*.jsonl.xz)
[ -e "${kept[0]}" ] || fail "no shard in $unpacked/random12all: unpack results/random12all.tar.xz there"
$summarize "${kept[@]}" > kept.txt
diff <(table kept.txt) <(table "$src/laboratory/results/random12all_shards.md") ||
  fail "results/random12all/ does not add up to the table of results/random12all_shards.md"
grep -q 'stopped early' kept.txt && fail "a kept random12all shard is unfinished"
# Set 3 of the 12 random points (the package's reading), kept whole, gives its table in stream_topcom.md.
set3=$src/laboratory/results/random12_set3.jsonl.xz
$summarize "$set3" > set3.txt
awk '/^## 12 random integer points, set 3/ { on = 1; next } on && /^## / { exit } on' \
  "$src/laboratory/results/stream_topcom.md" > set3_section.md
diff <(table set3.txt) <(table set3_section.md) ||
  fail "results/random12_set3.jsonl.xz does not give the set 3 table of results/stream_topcom.md"
grep -q 'stopped early' set3.txt && fail "the kept set 3 file is unfinished"
# The three sets run with a priority per start, kept whole, give their tables in stream_topcom.md.
for set in 1 2 3; do
  kept_set=$unpacked/random12_per_start/set$set.jsonl.xz
  $summarize "$kept_set" > per_start_set$set.txt
  awk -v head="### Set $set, a priority per start" '$0 == head { on = 1; next } on && /^##/ { exit } on' \
    "$src/laboratory/results/stream_topcom.md" > per_start_set$set.md
  [ "$(table per_start_set$set.md | wc -l)" -ge 3 ] || fail "stream_topcom.md has no table for set $set per start"
  diff <(table per_start_set$set.txt) <(table per_start_set$set.md) ||
    fail "results/random12_per_start/set$set.jsonl.xz does not give its table in results/stream_topcom.md"
  grep -q 'stopped early' per_start_set$set.txt && fail "the kept set $set per start is unfinished"
done
echo "streamed shards: all checks passed"
