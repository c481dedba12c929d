#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The fixed-order loops with the fewest swaps: the random integer sets of N
# points (sets 1 to 40), every TOPCOM triangulation as a start, fixed-order
# seeds 1 to SEEDS, each of the 36 readings, at most 12 cycles (traced on to
# 96 for loops that close later). Every loop is certified by the independent
# checker (experiment_priority_loops), which counts the swaps of one turn.
# Prints, per reading, the fewest swaps in a certified loop and the first
# set, seed and triangulation (in TOPCOM's order) that has it.
#
#   fewest_swap_loops.sh [N [SEEDS]]     (default: 6 points, seeds 1 to 1000)
set -euo pipefail
cd "$(dirname "$0")/../.."
n=${1:-6}
seeds=${2:-1000}
for set in $(seq 1 40); do
  ./build/bin/experiment_priority_loops random-integer:$n:$set "$seeds" 12 all |
    awk -v set="$set" '/^reading /{r=$2} /^fewest swaps in a certified loop: [0-9]/{print r, $7, set, $9, $11}'
done | awk '
  { gsub(/[,)]/, "", $4); gsub(/[,)]/, "", $5)
    if (!($1 in fewest) || $2 + 0 < fewest[$1]) { fewest[$1] = $2 + 0; where[$1] = "set " $3 ", seed " $4 ", triangulation " $5 } }
  END { for (r in fewest) print r ": " fewest[r] " swaps (" where[r] ")" }' | sort
