#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# laboratory/scripts/certify_case_loops.py (a ctest test): the cases that
# edge_swap_lab experiment saves from scrambled starts of the 3x3x2 grid, under
# every reading, are replayed with traces and checked apart; every fixed-order
# run at the limit is a certified loop, and their count per reading is the
# experiment's. A run that ends after the limit is told apart; runs traced too
# briefly, or a checker that refuses, make it exit 1; bad arguments, a bad case
# and a bad output file exit 2 with no file written.
#
#   case_loop_certification.sh EDGE_SWAP_LAB CHECK_TRACE SOURCE_DIR WORK_DIR
set -euo pipefail
edge_swap=${1:?usage: case_loop_certification.sh EDGE_SWAP_LAB CHECK_TRACE SOURCE_DIR WORK_DIR}
check_trace=${2:?}
script=${3:?}/laboratory/scripts/certify_case_loops.py
work=${4:?}
rm -rf "$work"
mkdir -p "$work"
fail() {
  echo "FAILED: $*" >&2
  exit 1
}
certify() { python3 "$script" "$@" --edge-swap-lab "$edge_swap" --check-trace "$check_trace"; }

"$edge_swap" experiment -o "$work/runs.jsonl" --families grid-3x3x2 --sizes 18 --seeds 1-6 --starts scramble:1000 \
  --strategies helper --orders priority,random --readings all --max-cycles 200 --threads 1 --cases "$work/cases" > /dev/null
certify "$work/cases" "$work/loops.jsonl" --jobs 2 > "$work/table.md" || fail "exit $? on the grid's cases"

# Per reading: the experiment's fixed-order runs at the limit, against the certified loops.
python3 - "$work/runs.jsonl" "$work/loops.jsonl" <<'PY' || fail "the certified loops are not the runs at the limit"
import collections, json, sys
at_limit = collections.Counter()
for line in open(sys.argv[1]):
    d = json.loads(line)
    if d.get("order") == "priority" and d.get("ending") == "cycle limit reached":
        at_limit[d["key"].split("|")[6]] += 1
certified = collections.Counter()
for line in open(sys.argv[2]):
    d = json.loads(line)
    assert d["status"] in ("certified", "not certifiable (order random)"), d
    if d["status"] == "certified":
        assert d["loop_to"] > d["loop_from"] and d["loop_swaps"] > 0, d
        certified[d["reading"]] += 1
assert sum(at_limit.values()) >= 10, at_limit  # the sample has loops to certify
assert at_limit == certified, (at_limit, certified)
print(sum(certified.values()), "loops certified in", len(certified), "readings")
PY
grep -q "^| until-destroyed,pass-over,no-swap,same-cycle | priority |" "$work/table.md" || fail "no table row"

# A second call resumes: nothing is replayed again.
cp "$work/loops.jsonl" "$work/first.jsonl"
certify "$work/cases" "$work/loops.jsonl" > /dev/null || fail "the resumed call failed"
cmp -s "$work/loops.jsonl" "$work/first.jsonl" || fail "the resumed file changed"

# A run at the limit that ends later (seed 1,786 ends on CGAL's triangulation at cycle 280),
# and runs traced too briefly to be settled (exit 1).
"$edge_swap" experiment -o "$work/later.jsonl" --families grid-3x3x2 --sizes 18 --seeds 1786 --starts scramble:1000 \
  --strategies helper --orders priority --readings "never-cleared,any-tetrahedron,no-swap" --max-cycles 200 \
  --threads 1 --cases "$work/later_cases" > /dev/null 2>&1
certify "$work/later_cases" "$work/later_loops.jsonl" > /dev/null || fail "exit $? on a run that ends later"
grep -q '"ends_on_delaunay": true.*"rounds": 280.*"status": "ended later"' "$work/later_loops.jsonl" ||
  fail "seed 1786 did not end later on CGAL's triangulation: $(cat "$work/later_loops.jsonl")"
set +e
certify "$work/cases" "$work/short.jsonl" --trace-limit 3 > /dev/null
rc=$?
set -e
[ $rc -eq 1 ] && grep -q '"not settled"' "$work/short.jsonl" || fail "runs traced to cycle 3: exit $rc"

# A checker that refuses every trace: exit 1, and the refusal is in the lines.
printf '#!/bin/sh\necho "{\\"confirmed\\":false,\\"error\\":\\"refused\\"}"\nexit 1\n' > "$work/refuse"
chmod +x "$work/refuse"
set +e
python3 "$script" "$work/cases" "$work/refused.jsonl" --edge-swap-lab "$edge_swap" --check-trace "$work/refuse" > /dev/null 2>&1
rc=$?
set -e
[ $rc -eq 1 ] && grep -q '"checker refused"' "$work/refused.jsonl" || fail "a refusing checker: exit $rc"

# Bad arguments and input: exit 2, a message, no file.
mkdir "$work/empty" "$work/bad_case" "$work/bad_limit"
echo '{"points": [' > "$work/bad_case/broken.json"
python3 -c "
import json, os, sys
name = sorted(os.listdir(sys.argv[1]))[0]
case = json.load(open(os.path.join(sys.argv[1], name)))
case['max_cycles'] = 1e30
json.dump(case, open(os.path.join(sys.argv[2], name), 'w'))" "$work/cases" "$work/bad_limit"
echo 'not json' > "$work/bad_out.jsonl"
for args in "$work/none $work/bad.jsonl" "$work/empty $work/bad.jsonl" "$work/bad_case $work/bad.jsonl" \
            "$work/cases $work/bad.jsonl --jobs 0" "$work/cases $work/bad_out.jsonl" "$work/bad_limit $work/bad.jsonl"; do
  read -ra a <<< "$args"
  set +e
  certify "${a[@]}" > /dev/null 2> "$work/err.txt"
  rc=$?
  set -e
  [ $rc -eq 2 ] || fail "'$args' exited $rc, not 2"
  [ -s "$work/err.txt" ] || fail "'$args' printed no message"
  [ ! -e "$work/bad.jsonl" ] || fail "'$args' wrote a file"
done
grep -qF "broken.json" <(certify "$work/bad_case" "$work/bad.jsonl" 2>&1) || fail "the bad case is not named"
[ "$(cat "$work/bad_out.jsonl")" = "not json" ] || fail "the bad output file was changed"
echo "certify_case_loops.py: every fixed-order run at the limit certified, resumed, refusals and bad input caught"
