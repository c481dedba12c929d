#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The trap scan (a ctest test): experiment_adversarial_orders --traps finds the
# 12-point trap (with integer coordinates, so that TOPCOM can read them) and
# writes a certificate that check_tag_bounds.py certifies; it finds no trap
# among every TOPCOM triangulation of a random 7-point set; it refuses bad
# starts with exit 2 and no certificate; scan_traps.py scans and resumes;
# --delaunay-first ends the run from the trap in its first cycle under no-swap.
#
#   trap_scan.sh EXPERIMENT SOURCE_DIR WORK_DIR
set -euo pipefail
program=${1:?usage: trap_scan.sh EXPERIMENT SOURCE_DIR WORK_DIR}
source_dir=${2:?}
work=${3:?}
here=$source_dir/laboratory/test
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
grep -qF "1 starts, 0 with CGAL's triangulation in their set, 0 undecided, traps 1" "$work/out.txt" || fail "$(cat "$work/out.txt")"
python3 "$source_dir/laboratory/checker/check_tag_bounds.py" "$work/trap.json" | grep -qF "certified: 2 triangulations" ||
  fail "check_tag_bounds.py does not certify the scan's certificate"

# Under pass-over: the checker takes the narrower help swaps and says which readings it covers.
"$program" --traps "$trap" until-destroyed,pass-over,no-swap 1000 "$work/pass_over.json" > /dev/null
python3 "$source_dir/laboratory/checker/check_tag_bounds.py" "$work/pass_over.json" |
  grep -qF "certified: 2 triangulations, closed under every visit; none is CGAL's triangulation; no state ends a run under no-swap-no-tag (the 12 readings with pass-over or facet-cells)" ||
  fail "check_tag_bounds.py on the pass-over certificate"

# Every TOPCOM triangulation of a random 7-point set, every reading but never-cleared's: no trap.
"$program" --traps random-integer:7:3 next-cycle 10000 > "$work/seven.txt"
starts=$(awk '/points, .* starts$/ {print $3}' "$work/seven.txt")
[ "${starts:-0}" -gt 10 ] || fail "random-integer:7:3: $(cat "$work/seven.txt")"
for lifetime in until-destroyed cleared-each-cycle; do
  for condition in pass-over facet-cells any-tetrahedron; do
    for ending in no-swap no-swap-no-tag; do
      grep -qF "reading $lifetime,$condition,$ending: $starts starts, $starts with CGAL's triangulation in their set, 0 undecided, traps 0" \
        "$work/seven.txt" || fail "random-integer:7:3, $lifetime,$condition,$ending: $(cat "$work/seven.txt")"
    done
  done
done

# --delaunay-first: the first cycle, locally Delaunay facets first, ends the run stuck exactly under the 18 no-swap readings.
"$program" --delaunay-first "$trap" all "$work/first.jsonl" > "$work/first.txt"
[ "$(grep -c "1 where plain swapping is stuck; the first cycle, locally Delaunay facets first, ends 1 runs stuck and 0 on" \
  "$work/first.txt")" = 18 ] || fail "--delaunay-first: $(cat "$work/first.txt")"
[ "$(grep -c "ends 0 runs stuck" "$work/first.txt")" = 18 ] || fail "--delaunay-first: $(cat "$work/first.txt")"
grep -q "until-destroyed,pass-over,no-swap: .* ends 1 runs stuck" "$work/first.txt" || fail "$(cat "$work/first.txt")"
[ "$(tail -n 1 "$work/first.jsonl")" = '{"end":"stuck","rounds":1}' ] || fail "--delaunay-first: the trace's end"
# Points TOPCOM cannot read (not integers), for every mode that enumerates: exit 2, not an abort.
python3 -c "import json, sys; c = json.load(open(sys.argv[1])); c['points'][0][0] += 0.5; \
json.dump(c, open(sys.argv[2], 'w'))" "$trap" "$work/half.json"
for mode in --delaunay-first --tag-bounds --effective --traps; do
  status=0
  if [ $mode = --delaunay-first ]; then set -- until-destroyed,pass-over,no-swap; else set -- until-destroyed,pass-over,no-swap 10; fi
  "$program" $mode "topcom:$work/half.json" "$@" > /dev/null 2> "$work/error.txt" || status=$?
  [ "$status" = 2 ] || fail "$mode on points that are not integers: exit $status, not 2"
  grep -qF "integer coordinates" "$work/error.txt" || fail "$mode: $(cat "$work/error.txt")"
done
status=0
PATH=/nonexistent "$program" --delaunay-first random-integer:6:1 all > /dev/null 2> "$work/error.txt" || status=$?
[ "$status" = 2 ] && grep -qF "TOPCOM is not installed" "$work/error.txt" ||
  fail "--delaunay-first without TOPCOM: exit $status, $(cat "$work/error.txt")"
for args in "$trap" "$trap no-such-reading" "$work/missing.json until-destroyed,pass-over,no-swap"; do
  status=0
  # shellcheck disable=SC2086 # the arguments are split on purpose
  "$program" --delaunay-first $args > /dev/null 2> "$work/error.txt" || status=$?
  [ "$status" = 2 ] || fail "--delaunay-first $args: exit $status, not 2"
done

# --shard I/N: three shards scan each start once, and their counts add up to the whole scan's.
sharded=0
for i in 0 1 2; do
  "$program" --traps random-integer:7:3 until-destroyed,pass-over,no-swap 10000 --shard $i/3 > "$work/shard_$i.txt"
  grep -qF ", shard $i/3 (the starts numbered $i modulo 3)" "$work/shard_$i.txt" || fail "shard $i: $(cat "$work/shard_$i.txt")"
  n=$(awk '/^reading / {print $3}' "$work/shard_$i.txt")
  grep -qF "reading until-destroyed,pass-over,no-swap: $n starts, $n with CGAL's triangulation in their set, 0 undecided, traps 0" \
    "$work/shard_$i.txt" || fail "shard $i: $(cat "$work/shard_$i.txt")"
  sharded=$((sharded + n))
done
[ "$sharded" = "$starts" ] || fail "the shards scanned $sharded starts, not $starts"
for value in 3/3 1/0 x 1 "" "0/2 extra"; do
  status=0
  # shellcheck disable=SC2086 # "0/2 extra" is two arguments on purpose
  "$program" --traps random-integer:7:3 until-destroyed,pass-over,no-swap 100 --shard $value > /dev/null 2>&1 || status=$?
  [ "$status" = 2 ] || fail "--shard '$value': exit $status, not 2"
done
# Bad point-set names: exit 2 with a message naming the problem (laboratory_arguments.h).
for bad in "random-integer:3:1|N is from 4 to 100000000" "random-integer:7x:1|is not random-integer:N:SET" \
           "random-integer:-5:1|is not random-integer:N:SET" "random-integer:7:4294967296|at most 4294967295" \
           "family:nosuch:7:1|unknown point family 'nosuch'" "family:cospherical:20001:1|at most 20000 points" \
           "nosuch|SOURCE is random-integer:N:SET"; do
  status=0
  "$program" --traps "${bad%%|*}" until-destroyed,pass-over,no-swap 100 > /dev/null 2> "$work/error.txt" || status=$?
  [ "$status" = 2 ] && grep -qF "${bad#*|}" "$work/error.txt" || fail "${bad%%|*}: exit $status, $(cat "$work/error.txt")"
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
scan="$source_dir/laboratory/scripts/scan_traps.py"
both=until-destroyed,pass-over,no-swap-no-tag+until-destroyed,any-tetrahedron,no-swap-no-tag
for round in 1 2; do
  EXPERIMENT_ADVERSARIAL_ORDERS=$program python3 "$scan" subsets "$work/eight.json" 7 $both "$work/subsets" \
    > "$work/subsets_$round.txt"
  [ "$(wc -l < "$work/subsets/summary.txt")" = 16 ] || fail "round $round: $(cat "$work/subsets/summary.txt")"
  grep -qE "^until-destroyed,pass-over,no-swap-no-tag 8 [0-9]+ 0$" "$work/subsets_$round.txt" ||
    fail "round $round: $(cat "$work/subsets_$round.txt")"
done
cmp -s "$work/subsets_1.txt" "$work/subsets_2.txt" || fail "the resumed scan's totals differ"
# The same in two shards, each in its own OUTDIR: `total` adds them up to the same totals.
for i in 0 1; do
  EXPERIMENT_ADVERSARIAL_ORDERS=$program python3 "$scan" subsets "$work/eight.json" 7 $both "$work/subsets_shard$i" \
    --shard $i/2 > /dev/null
  grep -q "^0-1-2-3-4-5-6 shard $i/2 reading " "$work/subsets_shard$i/summary.txt" || fail "shard $i's summary"
done
python3 "$scan" total "$work/subsets_shard0" "$work/subsets_shard1" > "$work/subsets_sharded.txt"
cmp -s "$work/subsets_1.txt" "$work/subsets_sharded.txt" || fail "the shards' totals: $(cat "$work/subsets_sharded.txt")"
python3 "$scan" total "$work/subsets_shard0" > "$work/half.txt"
[ "$(grep -c "^incomplete: .* 1 of 2 shards$" "$work/half.txt")" = 16 ] || fail "one shard of two: $(cat "$work/half.txt")"
grep -qE "^until-destroyed,pass-over,no-swap-no-tag" "$work/half.txt" && fail "one shard of two counted: $(cat "$work/half.txt")"
# Random slabs and caps of 6 points, and bad arguments (exit 2, no traceback).
for family in slab cap; do
  EXPERIMENT_ADVERSARIAL_ORDERS=$program python3 "$scan" $family 6 1-3 $both "$work/$family" > "$work/$family.txt"
  grep -qE "^until-destroyed,any-tetrahedron,no-swap-no-tag 3 [0-9]+ 0$" "$work/$family.txt" ||
    fail "$family: $(cat "$work/$family.txt")"
  grep -q "^${family}_6_3 reading until-destroyed,pass-over" "$work/$family/summary.txt" || fail "$family: no set 3"
done
for arguments in "slab 6 3-1 $both $work/bad" "cap x 1-2 $both $work/bad" "subsets $work/missing.json 6 $both $work/bad" \
  "subsets $work/eight.json 9 $both $work/bad" "subsets $work/eight.json 6 $both $work/bad 10 1,99" \
  "subsets $work/eight.json 6 $both $work/bad 0" "nothing" "slab 6 1-2 $both $work/bad --shard 2/2" \
  "slab 6 1-2 $both $work/bad --shard" "total" "total $work/bad" "slab 6 1-2 $both $work/eight.json"; do
  status=0
  python3 "$scan" $arguments > /dev/null 2> "$work/error.txt" || status=$?
  [ "$status" = 2 ] || fail "scan_traps.py $arguments: exit $status, not 2"
  grep -q "^scan_traps.py: " "$work/error.txt" && ! grep -q Traceback "$work/error.txt" ||
    fail "scan_traps.py $arguments: $(cat "$work/error.txt")"
done
[ ! -e "$work/bad/summary.txt" ] || fail "a refused scan wrote a summary"
echo "trap scan: all checks passed"
