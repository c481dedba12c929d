#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The trap scan (a ctest test): experiment_adversarial_orders --traps finds the
# 12-point trap (with integer coordinates, so that TOPCOM can read them) and
# writes a certificate that check_tag_bounds.py certifies; it finds no trap
# among every TOPCOM triangulation of a random 7-point set; it refuses bad
# starts with exit 2 and no certificate; scan_traps.py scans and resumes.
#
#   trap_scan.sh EXPERIMENT SOURCE_DIR WORK_DIR
set -euo pipefail
program=${1:?usage: trap_scan.sh EXPERIMENT SOURCE_DIR WORK_DIR}
source_dir=${2:?}
work=${3:?}
here=$source_dir/test/Edge_swapping_3
trap=$here/fixtures/trap_12_points_integer.json
rm -rf "$work"
mkdir -p "$work"
fail() {
  echo "FAILED: $*" >&2
  exit 1
}

# The trap, under the widest help swaps: certified apart, the same set as the kept certificate's.
"$program" --traps "$trap" until-destroyed,any-tetrahedron,no-swap-no-tag 1000 "$work/trap.json" > "$work/out.txt"
grep -qF "start 0: a trap under until-destroyed,any-tetrahedron,no-swap-no-tag, 2 triangulations, 0 with a state" \
  "$work/out.txt" || fail "the trap: $(cat "$work/out.txt")"
grep -qF "1 starts, 0 reach CGAL's triangulation, 0 undecided, traps 1" "$work/out.txt" || fail "$(cat "$work/out.txt")"
python3 "$here/check_tag_bounds.py" "$work/trap.json" | grep -qF "certified: 2 triangulations" ||
  fail "check_tag_bounds.py does not certify the scan's certificate"

# Under pass-over: the checker takes the narrower help swaps and says which readings it covers.
"$program" --traps "$trap" until-destroyed,pass-over,no-swap 1000 "$work/pass_over.json" > /dev/null
python3 "$here/check_tag_bounds.py" "$work/pass_over.json" |
  grep -qF "certified: 2 triangulations, closed under every visit; none is CGAL's triangulation; no state ends a run under no-swap-no-tag (the 12 readings with pass-over or facet-cells)" ||
  fail "check_tag_bounds.py on the pass-over certificate"

# Every TOPCOM triangulation of a random 7-point set, every reading but never-cleared's: no trap.
"$program" --traps random-integer:7:3 next-cycle 10000 > "$work/seven.txt"
starts=$(awk '/points, .* starts$/ {print $3}' "$work/seven.txt")
[ "${starts:-0}" -gt 10 ] || fail "random-integer:7:3: $(cat "$work/seven.txt")"
for lifetime in until-destroyed cleared-each-cycle; do
  for condition in pass-over facet-cells any-tetrahedron; do
    for ending in no-swap no-swap-no-tag; do
      grep -qF "reading $lifetime,$condition,$ending: $starts starts, $starts reach CGAL's triangulation, 0 undecided, traps 0" \
        "$work/seven.txt" || fail "random-integer:7:3, $lifetime,$condition,$ending: $(cat "$work/seven.txt")"
    done
  done
done

# Bad starts: exit 2, a message naming the file, no certificate.
python3 - "$trap" "$work" <<'EOF'
import json, sys
case = json.load(open(sys.argv[1]))
bad = dict(case, cells=case['cells'][1:])  # a cell missing: no triangulation of the points
json.dump(bad, open(sys.argv[2] + '/hole.json', 'w'))
open(sys.argv[2] + '/cut.json', 'w').write(json.dumps(case)[:100])
EOF
for bad in hole cut missing; do
  status=0
  "$program" --traps "$work/$bad.json" until-destroyed,pass-over,no-swap 1000 "$work/$bad.cert" > /dev/null \
    2> "$work/error.txt" || status=$?
  [ "$status" = 2 ] || fail "$bad.json: exit $status, not 2"
  grep -qF "$work/$bad.json: " "$work/error.txt" || fail "$bad.json: $(cat "$work/error.txt")"
  [ ! -e "$work/$bad.cert" ] || fail "$bad.json: a certificate was written"
done

# scan_traps.py: the 7-point subsets of 8 of the trap's points, then again (resumed: nothing new).
python3 -c "import json, sys; c = json.load(open(sys.argv[1])); c['points'] = c['points'][:8]; del c['cells']; \
c['start'] = 'placing'; json.dump(c, open(sys.argv[2], 'w'))" "$trap" "$work/eight.json"
scan="$source_dir/benchmark/Edge_swapping_3/scan_traps.py"
both=until-destroyed,pass-over,no-swap-no-tag+until-destroyed,any-tetrahedron,no-swap-no-tag
for round in 1 2; do
  EXPERIMENT_ADVERSARIAL_ORDERS=$program python3 "$scan" subsets "$work/eight.json" 7 $both "$work/subsets" \
    > "$work/subsets_$round.txt"
  [ "$(wc -l < "$work/subsets/summary.txt")" = 16 ] || fail "round $round: $(cat "$work/subsets/summary.txt")"
  grep -qE "^until-destroyed,pass-over,no-swap-no-tag 8 [0-9]+ 0$" "$work/subsets_$round.txt" ||
    fail "round $round: $(cat "$work/subsets_$round.txt")"
done
cmp -s "$work/subsets_1.txt" "$work/subsets_2.txt" || fail "the resumed scan's totals differ"
# Random slabs and caps of 6 points, and bad arguments (exit 2, no traceback).
for family in slab cap; do
  EXPERIMENT_ADVERSARIAL_ORDERS=$program python3 "$scan" $family 6 1-3 $both "$work/$family" > "$work/$family.txt"
  grep -qE "^until-destroyed,any-tetrahedron,no-swap-no-tag 3 [0-9]+ 0$" "$work/$family.txt" ||
    fail "$family: $(cat "$work/$family.txt")"
  grep -q "^${family}_6_3 reading until-destroyed,pass-over" "$work/$family/summary.txt" || fail "$family: no set 3"
done
for arguments in "slab 6 3-1 $both $work/bad" "cap x 1-2 $both $work/bad" "subsets $work/missing.json 6 $both $work/bad" \
  "subsets $work/eight.json 9 $both $work/bad" "subsets $work/eight.json 6 $both $work/bad 10 1,99" \
  "subsets $work/eight.json 6 $both $work/bad 0" "nothing"; do
  status=0
  python3 "$scan" $arguments > /dev/null 2> "$work/error.txt" || status=$?
  [ "$status" = 2 ] || fail "scan_traps.py $arguments: exit $status, not 2"
  grep -q "^scan_traps.py: " "$work/error.txt" && ! grep -q Traceback "$work/error.txt" ||
    fail "scan_traps.py $arguments: $(cat "$work/error.txt")"
done
[ ! -e "$work/bad/summary.txt" ] || fail "a refused scan wrote a summary"
echo "trap scan: all checks passed"
