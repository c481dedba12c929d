#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The fixed-order loops with the fewest swaps: the random integer sets of N
# points (sets 1 to 40), every TOPCOM triangulation as a start, fixed-order
# seeds 1 to SEEDS, each of the 36 readings, at most 12 cycles (traced on to
# 96 for loops that close later). Every loop is certified by the independent
# checker (experiment_priority_loops), which counts the swaps of one turn.
# Prints, per reading, the fewest swaps in a certified loop and the first
# set, seed and triangulation (in TOPCOM's order) that has it. With KEEP_DIR,
# each reading's loop is kept there as a case file, its cycle limit cut to
# the round at which its state comes back, and its trace (edge_swap_lab replay).
#
#   fewest_swap_loops.sh [N [SEEDS [KEEP_DIR]]]     (default: 6 points, seeds 1 to 1000)
set -euo pipefail
cd "$(dirname "$0")/../.."
n=${1:-6}
seeds=${2:-1000}
keep=${3:-}
table=$(for set in $(seq 1 40); do
  ./build/bin/experiment_priority_loops random-integer:$n:$set "$seeds" 12 all |
    awk -v set="$set" '/^reading /{r=$2} /^fewest swaps in a certified loop: [0-9]/{print r, $7, set, $9, $11}'
done | awk '
  { gsub(/[,)]/, "", $4); gsub(/[,)]/, "", $5)
    if (!($1 in fewest) || $2 + 0 < fewest[$1]) { fewest[$1] = $2 + 0; where[$1] = "set " $3 ", seed " $4 ", triangulation " $5 } }
  END { for (r in fewest) print r ": " fewest[r] " swaps (" where[r] ")" }' | sort)
printf '%s\n' "$table"
[ -n "$keep" ] || exit 0
mkdir -p "$keep"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%s\n' "$table" | while read -r reading swaps _ _ set _ seed _; do
  reading=${reading%:} set=${set%,} seed=${seed%,}
  rm -rf "$work/loop" && mkdir "$work/loop"
  # The seed's first certified loop: one with the fewest swaps, or this fails.
  ./build/bin/experiment_priority_loops random-integer:$n:$set "$seed-$seed" 12 "$reading" "$work/loop" > /dev/null
  name=loop_${n}_points_${reading//,/_}
  python3 - "$work/loop/$name" "$keep/$name" "$swaps" <<'PY'
import json, subprocess, sys
found, kept, swaps = sys.argv[1:]
case = json.load(open(found + '.json'))
swaps_in = {}
for line in open(found + '.trace.jsonl'):
    l = json.loads(line)
    if 'round' in l:
        swaps_in[l['round']] = l['swaps']
loop = json.loads(subprocess.run(['./build/bin/check_trace', found + '.trace.jsonl'],
                                 capture_output=True, text=True).stdout)['loop']
turn = sum(swaps_in[r] for r in range(loop['state_after_round'] + 1, loop['again_after_round'] + 1))
if turn != int(swaps):
    sys.exit(f'{found}: the seed\'s first loop has {turn} swaps, not {swaps}')
case['max_cycles'] = loop['again_after_round']
with open(kept + '.json', 'w') as f:
    json.dump(case, f, indent=1)
    f.write('\n')
PY
  ./build/bin/edge_swap_lab replay "$keep/$name.json" --trace "$keep/$name.trace.jsonl" > /dev/null
done
