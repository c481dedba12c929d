#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The helper in the fixed face order of SEEDS from every fine
# triangulation of CASE's points, under each reading of Algorithm 4; every
# run not ending on CGAL's triangulation is traced and replayed by the
# independent checker, which certifies the loops (experiment_priority_loops).
# One file per reading in OUTDIR; a reading whose file is complete is not run
# again, so the script resumes where it stopped. The readings left run in one
# process, on one TOPCOM enumeration when the starts are held. Two processes
# given disjoint reading lists share the work.
#
#   certify_fixed_order_loops.sh OUTDIR CASE SEEDS [--shard I/N] [--stream-batch B] [--hold N] [--trace-limit N] [--order-seeds per-set|per-start] [READING ...]
#   (default: all 36 readings)
#
# CASE and SEEDS as for experiment_priority_loops; the streams order the faces
# of set SET by seed SET, for example:
#   certify_fixed_order_loops.sh OUT family:grid-2x2x3:12:1 1
#   certify_fixed_order_loops.sh OUT family:two-spheres:12:2 2-2
# With --shard I/N, only the starts numbered I modulo N: give each shard its own
# OUTDIR (on any machine); summarize_certified_loops.py adds the shards up.
#   certify_fixed_order_loops.sh OUT/set1_shard0 random-integer:12:1 1-1 --shard 0/4 until-destroyed,pass-over,no-swap-no-tag
# --order-seeds per-start gives each start its own priority, as edge_swap
# experiment's option of that name does.
# --stream-batch B makes the shards blocks of B starts, those of edge_swap_lab experiment
# --stream --stream-batch B --shard I/N (4096 there by default), to certify a shard of a
# stream and set its counts beside the stream's.
# --stream-batch, --hold N, --trace-limit N and --order-seeds are passed on to experiment_priority_loops
# (--hold 0: starts known to be more than 10^6, a whole 12-point set, are
# streamed without enumerating them first; a shard of them is better held; runs
# at the limit are traced on to cycle 1600, or N, to certify loops that close
# after cycle 200).
set -euo pipefail
usage="usage: certify_fixed_order_loops.sh OUTDIR CASE SEEDS [--shard I/N] [--stream-batch B] [--hold N] [--trace-limit N] [--order-seeds per-set|per-start] [READING ...]"
out=${1:?$usage}
case_=${2:?$usage}
seeds=${3:?$usage}
shift 3
options=() # passed on
while [ "${1:-}" = --shard ] || [ "${1:-}" = --stream-batch ] || [ "${1:-}" = --hold ] || [ "${1:-}" = --trace-limit ] || [ "${1:-}" = --order-seeds ]; do
  options+=("$1" "${2:?$usage}")
  shift 2
done
bin=${EXPERIMENT_PRIORITY_LOOPS:-"$(cd "$(dirname "$0")/../.." && pwd)/build/bin/experiment_priority_loops"}
readings=("$@")
if [ ${#readings[@]} -eq 0 ]; then mapfile -t readings < <("$bin" --list-readings); fi
mkdir -p "$out"
pending=()
for reading in "${readings[@]}"; do
  if ! { [ -f "$out/$reading.txt" ] && grep -q '^all seeds:' "$out/$reading.txt"; }; then pending+=("$reading"); fi
done
[ ${#pending[@]} -gt 0 ] || exit 0
# One process for the readings left, so that TOPCOM enumerates the starts once (when they
# are held: see --hold). Its output is split by reading; a reading's file is kept when its
# last line ("all seeds: ...") comes, so a run stopped early keeps the readings it finished.
# A reading's seconds are from the end of the one before (the first's include the enumeration).
split_by_reading() {
  local header="" file="" reading="" line t0 t1
  t0=$(date +%s)
  while IFS= read -r line; do
    if [ -z "$header" ]; then
      header=$line
    elif [[ $line == "reading "* ]]; then
      reading=${line#reading }
      file="$out/$reading.txt"
      printf '%s\n%s\n' "$header" "$line" > "$file.part"
    else
      printf '%s\n' "$line" >> "$file.part"
      if [[ $line == "all seeds: "* ]]; then
        mv "$file.part" "$file"
        t1=$(date +%s)
        echo "$case_ seeds $seeds${options:+ ${options[*]}}, $reading: $((t1 - t0)) s, $(date -u +%FT%TZ)" >> "$out/progress.txt"
        t0=$t1
      fi
    fi
  done
}
status=0
"$bin" "$case_" "$seeds" 200 "${pending[*]}" "${options[@]}" | split_by_reading || status=$?
if [ $status != 0 ]; then
  # A failed run (a bad option: exit 2) leaves no part file, nor a directory it made.
  rm -f "$out"/*.part
  rmdir --ignore-fail-on-non-empty "$out"
  exit $status
fi
