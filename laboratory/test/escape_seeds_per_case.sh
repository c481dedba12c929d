#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# laboratory/scripts/escape_times_of_cases.sh (a ctest test): each case
# of a directory runs its own seed range (case n, in name order, seeds
# n*SEEDS+1 to n*SEEDS+SEEDS), its lines are the escape tool's own, a second
# call resumes without repeating a case, and bad arguments exit 2 with no file.
#
#   escape_seeds_per_case.sh EXPERIMENT_ESCAPE_TIMES SOURCE_DIR WORK_DIR
set -euo pipefail
program=${1:?usage: escape_seeds_per_case.sh EXPERIMENT_ESCAPE_TIMES SOURCE_DIR WORK_DIR}
source_dir=${2:?}
work=${3:?}
script=$source_dir/laboratory/scripts/escape_times_of_cases.sh
loops=$source_dir/laboratory/test/fixtures/loops
rm -rf "$work"
mkdir -p "$work/cases"
fail() {
  echo "FAILED: $*" >&2
  exit 1
}
cp "$loops/loop_6_points_until-destroyed_pass-over_no-swap-no-tag.json" "$work/cases/a.json"
cp "$loops/loop_6_points_never-cleared_any-tetrahedron_no-swap.json" "$work/cases/b.json"
export EXPERIMENT_ESCAPE_TIMES=$program

bash "$script" "$work/cases" 3 50 "$work/out.jsonl" 1
[ "$(wc -l < "$work/out.jsonl")" -eq 6 ] || fail "6 lines expected: $(cat "$work/out.jsonl")"
"$program" "$work/cases/a.json" 1 3 50 1 > "$work/expected.jsonl"
"$program" "$work/cases/b.json" 4 6 50 1 >> "$work/expected.jsonl"
# The same lines but for the run times.
untimed() { sed -E 's/"seconds":[^,]*,//' "$1"; }
[ "$(untimed "$work/out.jsonl")" = "$(untimed "$work/expected.jsonl")" ] || fail "the lines are not the tool's with seeds 1-3 and 4-6"
cp "$work/out.jsonl" "$work/first.jsonl"
grep -c '"seed":[1-6],' "$work/out.jsonl" | grep -qx 6 || fail "the seeds are not 1 to 6"

# A second call finds both cases in the file and runs nothing.
bash "$script" "$work/cases" 3 50 "$work/out.jsonl" 1
cmp -s "$work/out.jsonl" "$work/first.jsonl" || fail "the resumed file changed"

# Bad arguments: exit 2, a message, and no file.
for args in "$work/cases 0 50" "$work/cases 3 x" "$work/cases 3 50 $work/bad.jsonl 1e3" "$work/none 3 50"; do
  set +e
  read -ra a <<< "$args"
  [ ${#a[@]} -eq 3 ] && a+=("$work/bad.jsonl")
  bash "$script" "${a[@]}" 2> "$work/err.txt"
  rc=$?
  set -e
  [ $rc -eq 2 ] || fail "'$args' exited $rc, not 2"
  [ -s "$work/err.txt" ] || fail "'$args' printed no message"
  [ ! -e "$work/bad.jsonl" ] || fail "'$args' wrote a file"
done
mkdir "$work/empty"
set +e
bash "$script" "$work/empty" 3 50 "$work/bad.jsonl" 2> "$work/err.txt"
rc=$?
set -e
[ $rc -eq 2 ] && grep -qF "no case file" "$work/err.txt" && [ ! -e "$work/bad.jsonl" ] || fail "an empty directory: exit $rc"
echo "escape_times_of_cases.sh: seeds per case, resumed, bad arguments refused"
