#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Tag-bound sets (experiment_adversarial_orders --tag-bounds) from every TOPCOM
# triangulation of random integer sets, under the readings of Algorithm 4:
# from how many starts no order at all reaches CGAL's triangulation. Prints
# one line per size, set and reading, then per size and reading: starts,
# starts whose set closed, and starts from which no order reaches CGAL's
# triangulation.
#
#   tag_bounds_sets.sh [SIZES [READING [SETS [MAX_TRIANGULATIONS]]]]
#
# Defaults: sizes "6 7", all 36 readings, sets 1-40, 100,000 triangulations.
set -euo pipefail
cd "$(dirname "$0")/../.."
sizes=${1:-6 7}
reading=${2:-all}
sets=${3:-$(seq 1 40)}
most=${4:-100000}
for n in $sizes; do
  for set in $sets; do
    ./build/bin/experiment_adversarial_orders --tag-bounds random-integer:$n:$set "$reading" "$most" |
      awk -v n=$n -v set=$set '/^reading/{print n, set, $0}'
  done
done | while IFS= read -r line; do # each line to standard error too
  printf '%s\n' "$line" >&2
  printf '%s\n' "$line"
done | awk '
  { k = $1 " " $4; sub(":", "", k); starts[k] += $5; closed[k] += $7; unreached[k] += $NF }
  END { print "points reading starts closed no-order-reaches-CGAL"; fflush()
        for (k in starts) print k, starts[k], closed[k], unreached[k] | "sort" }'
