#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The adversarial order class on random integer sets (40 sets of each size),
# every TOPCOM triangulation as a start, under the readings of Algorithm 4
# (experiment_adversarial_orders, at most 20,000 states per start; with
# same-cycle the adversary chooses each cycle's sweep). Every loop found is certified by the independent
# checker. Prints one line per size, set and reading, then per size and
# reading: starts, starts settled, starts with a loop, sets with a loop, the
# fewest swaps in a loop, the starts from which uniformly random orders end
# the run with probability one (every state reached can still end it: exact
# for settled starts), and those from which an end that is not Delaunay can
# be reached.
#
#   adversarial_orders.sh [SIZES [READING [SETS [SEARCH [MAX_STATES]]]]]
#
# SEARCH "effective" runs the search over changing visits (--effective: the
# same answers, much faster from 7 points on);
# MAX_STATES (default 20000) bounds the states per start.
# Defaults: sizes "5 6", all 36 readings ("next-cycle" or "same-cycle" for
# 18 of them), sets 1-40 (3 minutes on one core). At 7 points a start takes
# about 0.2 s under the package's reading (`adversarial_orders.sh 7
# until-destroyed,pass-over,no-swap-no-tag`), about 1 s under some others;
# under the never-cleared readings the first start of set 1 had not settled
# after 40 s.
set -euo pipefail
cd "$(dirname "$0")/../.."
sizes=${1:-5 6}
reading=${2:-all}
sets=${3:-$(seq 1 40)}
search=()
case ${4:-full} in
  full) ;;
  effective) search=(--effective) ;;
  *) echo "adversarial_orders.sh: SEARCH is full or effective" >&2; exit 2 ;;
esac
max_states=${5:-20000}
for n in $sizes; do
  for set in $sets; do
    ./build/bin/experiment_adversarial_orders "${search[@]}" random-integer:$n:$set "$reading" "$max_states" |
      awk -v n=$n -v set=$set '/^reading/{print n, set, $0}'
  done
done | while IFS= read -r line; do # each line to standard error too, through its descriptor
  printf '%s\n' "$line" >&2
  printf '%s\n' "$line"
done | awk '
  { n = $1; r = $4; sub(":", "", r); k = n " " r
    starts[k] += $5; settled[k] += $7; loops[k] += $9; sets[k] += ($9 > 0)
    if ($9 > 0) { f = $0; sub(/.*fewest swaps /, "", f); sub(/,.*/, "", f); if (!(k in fewest) || f + 0 < fewest[k]) fewest[k] = f + 0 }
    p = $0; sub(/.*probability one from /, "", p); sub(/;.*/, "", p); surely[k] += p
    o = $0; sub(/.*is reachable from /, "", o); off[k] += o }
  END { print "points reading starts settled with-loop sets-with-loop fewest-swaps ends-with-probability-one can-end-off-Delaunay"
        for (k in starts) print k, starts[k], settled[k], loops[k], sets[k], (k in fewest ? fewest[k] : "-"), surely[k], off[k] }' | sort
