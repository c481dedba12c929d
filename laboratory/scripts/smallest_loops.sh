#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The smallest loops of the helper strategy under the fixed face order: random
# integer sets of 5, 6 and 7 points (40 sets each), every TOPCOM triangulation
# as a start, fixed-order seeds 1 to 20, each of the 36 readings of Algorithm 4,
# at most 100 cycles. Each run that does not end on CGAL's triangulation is
# replayed by the independent checker (experiment_priority_loops), and the
# first certified loop of each size and reading is kept in LOOP_DIR (default
# /tmp/smallest_loops) as a case file with its trace.
# Output, one line per size, reading and set (totals over the seeds):
# laboratory/results/smallest_loops.txt. About an hour on one core.
set -euo pipefail
cd "$(dirname "$0")/../.."
loops=${LOOP_DIR:-/tmp/smallest_loops}
mkdir -p "$loops"
for n in 5 6 7; do
  for set in $(seq 1 40); do
    ./build/bin/experiment_priority_loops random-integer:$n:$set 20 100 all "$loops" |
      awk -v n=$n -v set=$set '/^reading /{r=$2} /^all seeds/{print n, r, set, $0}'
  done
done
