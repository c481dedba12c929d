#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The smallest loops of the helper strategy under the fixed face order: random
# integer sets of 5, 6 and 7 points (40 sets each), every TOPCOM triangulation
# as a start, fixed-order seeds 1 to 20, every reading of Algorithm 4, at most
# 100 cycles. Each run that does not end on CGAL's triangulation is replayed by
# the independent checker (experiment_priority_loops). One line per set and
# reading: size, reading, set, and the totals over the seeds.
# Output: doc/Edge_swapping_3/results/smallest_loops.txt (about 15 minutes here).
set -euo pipefail
cd "$(dirname "$0")/../.."
for n in 5 6 7; do
  for r in until-destroyed,pass-over,no-swap-no-tag cleared-each-cycle,pass-over,no-swap-no-tag \
           until-destroyed,any-tetrahedron,no-swap-no-tag cleared-each-cycle,any-tetrahedron,no-swap-no-tag \
           until-destroyed,pass-over,no-swap cleared-each-cycle,pass-over,no-swap \
           until-destroyed,any-tetrahedron,no-swap cleared-each-cycle,any-tetrahedron,no-swap; do
    for set in $(seq 1 40); do
      echo "$n $r $set $(./build/bin/experiment_priority_loops random-integer:$n:$set 20 100 $r | tail -1)"
    done
  done
done
