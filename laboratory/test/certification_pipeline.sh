#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The laboratory's certification pipeline end to end (a ctest test): the 8
# points of fixtures/helper_priority_loop_8_points.json from each of their 131
# fine triangulations (TOPCOM), seeds 1 to 20, under two readings, through
# certify_fixed_order_loops.sh and summarize_certified_loops.py, whole and in
# three streamed shards (held or streamed, the same runs; directories that do
# not partition the starts refused). The counts are those of
# laboratory/doc/conjectures.md.
# With EDGE_SWAP_LAB, a priority per start (--order-seeds per-start) on 8 random
# integer points under all 36 readings: the runs at the limit are those of
# `edge_swap_lab experiment --order-seeds per-start`, start for start in number; and a
# shard of a stream in its blocks (--stream-batch) against the stream's tallies.
#
#   certification_pipeline.sh EXPERIMENT_PRIORITY_LOOPS SOURCE_DIR WORK_DIR [EDGE_SWAP_LAB]
set -euo pipefail
export EXPERIMENT_PRIORITY_LOOPS=${1:?usage: certification_pipeline.sh EXPERIMENT_PRIORITY_LOOPS SOURCE_DIR WORK_DIR}
source_dir=${2:?}
work=${3:?}
edge_swap=${4:-}
fixture=$source_dir/laboratory/test/fixtures/helper_priority_loop_8_points.json
certify=$source_dir/laboratory/scripts/certify_fixed_order_loops.sh
summarize=$source_dir/laboratory/scripts/summarize_certified_loops.py
readings=(until-destroyed,pass-over,no-swap-no-tag never-cleared,any-tetrahedron,no-swap,same-cycle)
rm -rf "$work"
mkdir -p "$work"
fail() {
  echo "FAILED: $*" >&2
  exit 1
}
# The table without its seconds column (times differ from run to run) and without the line
# saying which shards it adds up; its exit status is tested apart.
table() { { python3 "$summarize" "$@" || true; } | sed -E 's/ [0-9,]+ \|$/ |/; s/, [0-9,]+ s$//; / of [0-9]+ shards \(/d'; }

bash "$certify" "$work/whole" "$fixture" 1-20 "${readings[@]}"
whole=$(table "$work/whole")
echo "$whole"
python3 "$summarize" "$work/whole" > /dev/null || fail "the summary of every loop certified: exit $?"
grep -qF '| `until-destroyed,pass-over,no-swap-no-tag` | 2,620 | 174 | 174 | 0 | 0 | 0 |' <<< "$whole" ||
  fail "the package's reading: 2,620 runs, 174 loops certified"
grep -qF '| `never-cleared,any-tetrahedron,no-swap,same-cycle` | 2,620 | 445 | 445 | 0 | 0 | 0 |' <<< "$whole" ||
  fail "never-cleared,any-tetrahedron,no-swap,same-cycle: 2,620 runs, 445 loops certified"
# The two readings ran in one process (one TOPCOM enumeration); the second's file is that of a
# process of its own.
"$EXPERIMENT_PRIORITY_LOOPS" "$fixture" 1-20 200 "${readings[1]}" | cmp -s - "$work/whole/${readings[1]}.txt" ||
  fail "a reading run with another differs from it run alone"
[ "$(grep -c "^$fixture seeds 1-20, " "$work/whole/progress.txt")" = 2 ] || fail "progress.txt has not one line a reading"

# Three shards, streamed from TOPCOM (--hold 0), add up to the whole.
for s in 0 1 2; do bash "$certify" "$work/shard$s" "$fixture" 1-20 --shard $s/3 --hold 0 "${readings[@]}"; done
grep -q "^8 points, triangulations streamed, shard 1/3" "$work/shard1/${readings[0]}.txt" || fail "shard 1/3 not streamed"
[ "$(table "$work/shard0" "$work/shard1" "$work/shard2")" = "$whole" ] || fail "the three shards do not add up to the whole"
[ "$(table "$work/shard0")" != "$whole" ] || fail "one shard is the whole"
python3 "$summarize" "$work/shard2" "$work/shard0" | grep -qx "$fixture seeds 1-20: 2 of 3 shards (0, 2), modulo 3" ||
  fail "the summary does not say which shards it adds up"
# Held (44 starts) or, with more than --hold of them, streamed again a reading: the same runs.
"$EXPERIMENT_PRIORITY_LOOPS" "$fixture" 1-20 200 "${readings[*]}" --shard 1/3 > "$work/shard1_held.txt"
"$EXPERIMENT_PRIORITY_LOOPS" "$fixture" 1-20 200 "${readings[*]}" --shard 1/3 --hold 10 > "$work/shard1_over.txt"
grep -q "^8 points, 131 triangulations, shard 1/3" "$work/shard1_held.txt" || fail "shard 1/3 not held"
grep -q "^8 points, more than 10 starts in the shard, streamed, shard 1/3" "$work/shard1_over.txt" ||
  fail "shard 1/3 held with more starts than --hold"
cmp -s <(tail -n +2 "$work/shard1_held.txt") <(tail -n +2 "$work/shard1_over.txt") &&
  cmp -s <(tail -n +3 "$work/shard1_held.txt" | sed -n '1,/^all seeds/p') <(tail -n +3 "$work/shard1/${readings[0]}.txt") ||
  fail "shard 1/3 held, streamed and in its file differ"
# Not a partition: the same shard twice, or the whole beside a shard (exit 2, naming both).
for pair in "shard0 shard0" "whole shard1"; do
  status=0
  # shellcheck disable=SC2086 # two directory names
  python3 "$summarize" $(printf "$work/%s " $pair) > /dev/null 2> "$work/not_a_partition.txt" || status=$?
  [ $status = 2 ] || fail "$pair added up: exit $status, not 2"
  grep -q "${pair% *}.* and .*${pair#* }" "$work/not_a_partition.txt" || fail "$pair: the directories are not named"
done

# A complete reading is not run again.
before=$(wc -l < "$work/whole/progress.txt")
bash "$certify" "$work/whole" "$fixture" 1-20 "${readings[@]}"
[ "$(wc -l < "$work/whole/progress.txt")" = "$before" ] || fail "a complete reading ran again"

# A limit of 5 cycles: 216 runs at it. Traced on (to 8 x 5 cycles), 174 are loops and 42 end
# later on CGAL's triangulation; traced to 5 cycles only, 161 loops are certified and 55 runs
# are not settled, an error of the summary (exit 1). A directory that is not there: exit 2.
mkdir -p "$work/limit5" "$work/limit5_short"
"$EXPERIMENT_PRIORITY_LOOPS" "$fixture" 1-20 5 "${readings[0]}" > "$work/limit5/${readings[0]}.txt"
"$EXPERIMENT_PRIORITY_LOOPS" "$fixture" 1-20 5 "${readings[0]}" --trace-limit 5 > "$work/limit5_short/${readings[0]}.txt"
table "$work/limit5" | grep -qF '| 2,620 | 216 | 174 | 42 | 0 | 0 |' || fail "limit 5: 216 at it, 174 loops, 42 ending later"
table "$work/limit5_short" | grep -qF '| 2,620 | 216 | 161 | 0 | 55 | 0 |' || fail "trace limit 5: 161 loops, 55 not settled"
# Each loop the helper's driver found (its state came back) is traced once, to where it closed,
# and certified there; with a trace limit of 5, the 172 runs whose loop the driver had not
# found by cycle 5 are traced whole (to 5), and 117 of them are loops all the same.
driver_line() { grep -h '^loops the driver found: ' "$1"; }
first_return="certified traced to where it said the state came back"
[ "$(driver_line "$work/whole/${readings[0]}.txt")" = "loops the driver found: 174, $first_return: 174; runs at the trace limit traced whole: 0" ] ||
  fail "the package's reading: 174 loops found by the driver and certified by one trace each"
[ "$(driver_line "$work/limit5_short/${readings[0]}.txt")" = "loops the driver found: 44, $first_return: 44; runs at the trace limit traced whole: 172" ] ||
  fail "trace limit 5: 44 loops found by the driver, 172 runs traced whole"
status=0
python3 "$summarize" "$work/limit5_short" > /dev/null || status=$?
[ $status = 1 ] || fail "runs not settled: exit $status, not 1"
status=0
python3 "$summarize" "$work/not_there" 2> /dev/null || status=$?
[ $status = 2 ] || fail "a missing directory: exit $status, not 2"

# Bad options: exit 2, no output file.
for bad in "--shard 3/3" "--shard x" "--hold -1" "--trace-limit 199"; do
  status=0
  # shellcheck disable=SC2086 # the option and its value, split
  bash "$certify" "$work/bad" "$fixture" 1-20 $bad "${readings[0]}" 2> /dev/null || status=$?
  [ $status = 2 ] || fail "$bad: exit $status, not 2"
  [ ! -e "$work/bad" ] || fail "$bad: $work/bad was left"
done
status=0
"$EXPERIMENT_PRIORITY_LOOPS" "$fixture" 1-20 200 no-such-reading 2> /dev/null || status=$?
[ $status = 2 ] || fail "an unknown reading: exit $status, not 2"
# Bad point-set names, SEEDS and MAX_CYCLES: exit 2 with a message naming the problem.
for bad in "random-integer:3:1 1 200|N is from 4 to 100000000" "random-integer:8x:1 1 200|is not random-integer:N:SET" \
           "random-integer:-5:1 1 200|is not random-integer:N:SET" "family:grid-2x2x3:12 1 200|is not family:NAME:N:SEED" \
           "family:nosuch:8:1 1 200|unknown point family 'nosuch'" "$fixture 12x 200|SEEDS is LAST or FIRST-LAST" \
           "$fixture -1 200|SEEDS is LAST" "$fixture 2-1 200|SEEDS is LAST" "$fixture 1-4294967296 200|SEEDS is LAST" \
           "$fixture 1 0|MAX_CYCLES a whole number above 0" "$fixture 1 -3|MAX_CYCLES a whole number"; do
  status=0
  # shellcheck disable=SC2086 # CASE SEEDS MAX_CYCLES, split
  "$EXPERIMENT_PRIORITY_LOOPS" ${bad%%|*} > /dev/null 2> "$work/error.txt" || status=$?
  [ $status = 2 ] && grep -qF -- "${bad#*|}" "$work/error.txt" || fail "${bad%%|*}: exit $status, $(cat "$work/error.txt")"
done

# A priority per start: every run at the limit a certified loop, as many per reading as
# edge_swap_lab experiment leaves at the limit with the same seeds per start.
if [ -n "$edge_swap" ]; then
  bash "$certify" "$work/per_start" random-integer:8:1 1-1 --order-seeds per-start
  grep -q "^8 points, 132 triangulations, a priority per start" "$work/per_start/${readings[0]}.txt" ||
    fail "the per-start run does not say so"
  python3 "$summarize" "$work/per_start" > "$work/per_start.md" || fail "per start: a run at the limit not certified"
  grep -q '^readings complete: 36; 4,752 runs' "$work/per_start.md" || fail "per start: not 36 readings of 132 runs"
  "$edge_swap" experiment -o "$work/per_start.jsonl" --starts topcom --max-cycles 200 --threads 1 --strategies helper \
    --orders priority --families random-integer --sizes 8 --seeds 1 --readings all --order-seeds per-start > /dev/null 2>&1 ||
    fail "edge_swap_lab experiment --order-seeds per-start"
  python3 - "$work/per_start.jsonl" "$work/per_start.md" << 'PY' || fail "per start: the counts differ from edge_swap_lab experiment's"
import collections, json, re, sys
at_limit = collections.Counter()
for line in open(sys.argv[1]):
    run = json.loads(line)
    key = run["key"].split("|")
    reading = key[6] if len(key) > 6 else "until-destroyed,pass-over,no-swap-no-tag"  # the package's: no suffix
    at_limit[reading] += run["ending"] == "cycle limit reached"
rows = {m.group(1): int(m.group(2).replace(",", "")) for m in
        re.finditer(r"^\| `([^`]+)` \| [\d,]+ \| ([\d,]+) \|", open(sys.argv[2]).read(), re.M)}
assert len(rows) == 36 and sum(rows.values()) > 0, rows
assert all(rows[r] == at_limit[r] for r in rows), [(r, rows[r], at_limit[r]) for r in rows if rows[r] != at_limit[r]]
PY
  # The same points under the set's priority give other counts; the two are not added up.
  bash "$certify" "$work/per_set" random-integer:8:1 1-1 "${readings[0]}"
  row() { table "$1" | grep -F "| \`${readings[0]}\` |"; } # the package's reading's row
  [ -n "$(row "$work/per_set")" ] && [ "$(row "$work/per_set")" != "$(row "$work/per_start")" ] ||
    fail "the package's reading gives the same counts per start as per set"
  status=0
  python3 "$summarize" "$work/per_set" "$work/per_start" > /dev/null 2> "$work/mixed.txt" || status=$?
  [ $status = 2 ] || fail "per-set and per-start directories added up: exit $status, not 2"
  grep -q "per-set (.*per_set/.*) and per-start (.*per_start/" "$work/mixed.txt" || fail "the mixed directories are not named"
  status=0
  "$EXPERIMENT_PRIORITY_LOOPS" random-integer:8:1 1-1 200 --order-seeds per-each 2> /dev/null || status=$?
  [ $status = 2 ] || fail "--order-seeds per-each: exit $status, not 2"

  # A shard of a stream, in its blocks (--stream-batch): shard 1/3 of the 132 triangulations in
  # blocks of 16 is blocks 1, 4 and 7, 48 starts; under each of the 36 readings its runs at the
  # limit are those the stream's tallies count for the same shard, and every one is a loop.
  bash "$certify" "$work/stream_shard" random-integer:8:1 1-1 --shard 1/3 --stream-batch 16 --hold 0
  grep -q "^8 points, triangulations streamed, shard 1/3 in blocks of 16" "$work/stream_shard/${readings[0]}.txt" ||
    fail "the shard in blocks does not say so"
  python3 "$summarize" "$work/stream_shard" > "$work/stream_shard.md" || fail "stream shard: a run at the limit not certified"
  grep -q '^readings complete: 36; 1,728 runs, 86 at the limit, 86 certified loops' "$work/stream_shard.md" ||
    fail "stream shard: not 36 readings of 48 runs with 86 loops"
  # Shard 1/3 modulo 3 is other starts than shard 1/3 in blocks of 16: not added up (exit 2).
  bash "$certify" "$work/modulo_shard" random-integer:8:1 1-1 --shard 1/3 "${readings[0]}"
  status=0
  python3 "$summarize" "$work/stream_shard" "$work/modulo_shard" > /dev/null 2> "$work/partitions.txt" || status=$?
  [ $status = 2 ] && grep -q "in blocks of 16 and .*modulo_shard is shard 1/3 modulo 3 of random-integer:8:1 seeds 1-1" \
    "$work/partitions.txt" || fail "shards in blocks and modulo N added up: exit $status, not 2 naming both"
  "$edge_swap" experiment -o "$work/stream_shard.jsonl" --starts topcom --stream --stream-batch 16 --shard 1/3 \
    --max-cycles 200 --threads 1 --strategies helper --orders priority --families random-integer --sizes 8 --seeds 1 \
    --readings all > /dev/null 2>&1 || fail "edge_swap_lab experiment --stream --stream-batch 16 --shard 1/3"
  against=$source_dir/laboratory/scripts/certified_against_stream.py
  python3 "$against" --stream "$work/stream_shard.jsonl" --certified "$work/stream_shard" > "$work/against.md" ||
    fail "stream shard: the counts differ from the stream's (exit $?)"
  xz -c "$work/stream_shard.jsonl" > "$work/stream_shard.jsonl.xz"
  python3 "$against" --stream "$work/stream_shard.jsonl.xz" --certified "$work/stream_shard" | cmp -s - "$work/against.md" ||
    fail "the stream read from xz gives another table"
  grep -q '^36 of 36 readings agree; the stream has 86 fixed-order runs at the limit$' "$work/against.md" ||
    fail "stream shard: not 36 readings agreeing on 86 runs at the limit"
  grep -qF '| `until-destroyed,any-tetrahedron,no-swap` | 48 | 10 | 48 | 10 | 10 | 0 | yes |' "$work/against.md" ||
    fail "stream shard: until-destroyed,any-tetrahedron,no-swap is not 48 runs, 10 at the limit, 10 loops"
  # The same shard as one task of a job array (stream_and_certify_shard.sh): the same table, also
  # from the compressed tallies it keeps; run again, nothing is run again; bad arguments: exit 2
  # and no OUTDIR.
  task=$source_dir/laboratory/scripts/stream_and_certify_shard.sh
  EDGE_SWAP_LAB=$edge_swap bash "$task" "$work/task" random-integer:8:1 1 3 16 > "$work/task.txt" ||
    fail "stream_and_certify_shard.sh: exit $?"
  cmp -s "$work/task/against.md" "$work/against.md" || fail "the task's table differs from the shard's"
  grep -qx "36 of 36 readings agree; the stream has 86 fixed-order runs at the limit" "$work/task.txt" ||
    fail "the task does not say that the 36 readings agree"
  python3 "$against" --stream "$work/task/stream.jsonl.xz" --certified "$work/task/certified" |
    cmp -s - "$work/against.md" || fail "the task's kept tallies give another table"
  before="$(stat -c %Y "$work/task/stream.jsonl") $(wc -l < "$work/task/certified/progress.txt")"
  EDGE_SWAP_LAB=/nonexistent bash "$task" "$work/task" random-integer:8:1 1 3 16 > /dev/null ||
    fail "stream_and_certify_shard.sh run again: exit $?"
  [ "$(stat -c %Y "$work/task/stream.jsonl") $(wc -l < "$work/task/certified/progress.txt")" = "$before" ] ||
    fail "a task done ran again"
  for bad in "random-integer:8:1 3 3" "random-integer:8:1 x 3" "random-integer:8:1 1 3 0" "random-integer:8 1 3" \
             "family:grid-2x2x3:12 1 3" "family:nosuch:8:1 1 3" "random-integer:3:1 1 3" "random-integer:8:1 1"; do
    status=0
    # shellcheck disable=SC2086 # SET I N [BATCH], split
    EDGE_SWAP_LAB=$edge_swap bash "$task" "$work/task_bad" $bad > /dev/null 2> "$work/task_bad.txt" || status=$?
    [ $status = 2 ] && [ -s "$work/task_bad.txt" ] && [ ! -e "$work/task_bad" ] ||
      fail "stream_and_certify_shard.sh $bad: exit $status, not 2 with a message and no OUTDIR"
  done
  [ "$(grep -c ' instances in [0-9.]* s on 1 threads$' "$work/task/stream.log")" = 1 ] ||
    fail "the task's stream.log does not give the stream's time once"
  # Attempts that fail say their own messages alone (exit 2) and the log keeps every attempt's.
  printf '#!/bin/sh
echo "an attempt that failed" >&2
exit 1
' > "$work/failing_edge_swap"
  chmod +x "$work/failing_edge_swap"
  mkdir -p "$work/task_log"
  for attempt in 1 2; do
    status=0
    EDGE_SWAP_LAB=$work/failing_edge_swap bash "$task" "$work/task_log" random-integer:8:1 1 3 16 > /dev/null \
      2> "$work/task_log.txt" || status=$?
    [ $status = 2 ] && [ "$(cat "$work/task_log.txt")" = "an attempt that failed" ] ||
      fail "failed attempt $attempt: exit $status, not 2 with its own message alone"
  done
  EDGE_SWAP_LAB=$edge_swap bash "$task" "$work/task_log" random-integer:8:1 1 3 16 > /dev/null ||
    fail "stream_and_certify_shard.sh after two failed attempts: exit $?"
  [ "$(grep -c '^an attempt that failed$' "$work/task_log/stream.log")" = 2 ] &&
    [ "$(grep -c ' instances in [0-9.]* s on 1 threads$' "$work/task_log/stream.log")" = 1 ] ||
    fail "the log does not keep the three attempts"
  cmp -s "$work/task_log/against.md" "$work/against.md" || fail "the task run after failed attempts differs"
  # Keeping a task for the docs (write_all_readings_certified.py): only a shard of 64 of the
  # 12 random points of set 2 or 3 that agrees; else exit 2, a message, and nothing kept.
  keep=$source_dir/laboratory/scripts/write_all_readings_certified.py
  kept=${EDGE_SWAP_LAB_UNPACKED:-$source_dir/laboratory/results}/random12_set3_all_readings
  kept_files() { if [ -d "$kept" ]; then find "$kept" | wc -l; else echo 0; fi; }
  before=$(kept_files)
  for bad in "3 --add $work/task" "3 --add $work/nonexistent" "3 --add" "4" "1" "3 --bogus" "" "3 --check --add"; do
    status=0
    # shellcheck disable=SC2086 # the arguments, split
    python3 "$keep" $bad > /dev/null 2> "$work/keep_bad.txt" || status=$?
    [ $status = 2 ] && [ -s "$work/keep_bad.txt" ] || fail "write_all_readings_certified.py $bad: exit $status, not 2"
  done
  grep -q "not a shard of 64 of random-integer|12|3" <(python3 "$keep" 3 --add "$work/task" 2>&1) ||
    fail "write_all_readings_certified.py does not say that the 8-point task is not a shard of set 3"
  [ "$(kept_files)" = "$before" ] || fail "a refused task was kept"
  # The whole stream, its batches numbered 1 modulo 3 (--batches 1/3): the same table as the
  # shard's own stream. Another shard of it differs (exit 1); a shard's stream, or a --batches
  # that is not I/N with I < N, is refused (exit 2).
  "$edge_swap" experiment -o "$work/stream_whole.jsonl" --starts topcom --stream --stream-batch 16 \
    --max-cycles 200 --threads 1 --strategies helper --orders priority --families random-integer --sizes 8 --seeds 1 \
    --readings all > /dev/null 2>&1 || fail "edge_swap_lab experiment --stream --stream-batch 16"
  python3 "$against" --stream "$work/stream_whole.jsonl" --certified "$work/stream_shard" --batches 1/3 |
    cmp -s - "$work/against.md" || fail "--batches 1/3 of the whole stream gives another table than the shard's stream"
  status=0
  python3 "$against" --stream "$work/stream_whole.jsonl" --certified "$work/stream_shard" --batches 2/3 > /dev/null ||
    status=$?
  [ $status = 1 ] || fail "--batches 2/3 against shard 1/3: exit $status, not 1"
  for bad in "--stream $work/stream_shard.jsonl --batches 1/3" "--stream $work/stream_whole.jsonl --batches 3/3" \
             "--stream $work/stream_whole.jsonl --batches 1" "--stream $work/stream_whole.jsonl --batches -1/3"; do
    status=0
    python3 "$against" $bad --certified "$work/stream_shard" > /dev/null 2> "$work/against_bad.txt" || status=$?
    [ $status = 2 ] && [ -s "$work/against_bad.txt" ] || fail "certified against $bad: exit $status, not 2 with a message"
  done
  # Other starts (the per-start run) differ: exit 1. A stream cut short (as text or xz) or not JSON: exit 2.
  status=0
  python3 "$against" --stream "$work/stream_shard.jsonl" --certified "$work/per_start" > /dev/null || status=$?
  [ $status = 1 ] || fail "certified against other starts: exit $status, not 1"
  head -n 2 "$work/stream_shard.jsonl" > "$work/cut.jsonl"
  printf '{"tally": [1, 2]}\n' > "$work/not_a_stream.jsonl"
  xz -c "$work/stream_shard.jsonl" | head -c 200 > "$work/cut.jsonl.xz"
  for bad in "$work/cut.jsonl" "$work/not_a_stream.jsonl" "$work/not_there.jsonl" "$work/cut.jsonl.xz"; do
    status=0
    python3 "$against" --stream "$bad" --certified "$work/stream_shard" > /dev/null 2> "$work/against_bad.txt" || status=$?
    [ $status = 2 ] && grep -qF "$bad" "$work/against_bad.txt" || fail "certified against $bad: exit $status, not 2 naming it"
  done
  for bad in 0 x 99999999999999999999999; do
    status=0
    "$EXPERIMENT_PRIORITY_LOOPS" random-integer:8:1 1-1 200 --shard 1/3 --stream-batch $bad 2> /dev/null || status=$?
    [ $status = 2 ] || fail "--stream-batch $bad: exit $status, not 2"
  done
fi
echo "certification pipeline: all checks passed"
