#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Issue 13: the helper in a fixed order (seed 1) from every fine
# triangulation of the 2x2x3 grid, under each reading of Algorithm 4; every
# run still swapping at cycle 200 traced and certified a loop by the
# independent checker (experiment_priority_loops). One file per reading in
# OUTDIR; a reading whose file is complete is not run again, so the script
# resumes where it stopped.
#
#   certify_grid_loops.sh OUTDIR [READING ...]   (default: all 36 readings)
set -euo pipefail
out=${1:?usage: certify_grid_loops.sh OUTDIR [READING ...]}
shift
bin=${EXPERIMENT_PRIORITY_LOOPS:-"$(cd "$(dirname "$0")/../.." && pwd)/build/bin/experiment_priority_loops"}
readings=("$@")
if [ ${#readings[@]} -eq 0 ]; then
  for lifetime in until-destroyed cleared-each-cycle never-cleared; do
    for needs in pass-over any-tetrahedron facet-cells; do
      for ending in no-swap-no-tag no-swap; do
        for visit in "" ",same-cycle"; do readings+=("$lifetime,$needs,$ending$visit"); done
      done
    done
  done
fi
mkdir -p "$out"
for reading in "${readings[@]}"; do
  file="$out/$reading.txt"
  if [ -f "$file" ] && grep -q '^all seeds:' "$file"; then continue; fi
  t0=$(date +%s)
  "$bin" family:grid-2x2x3:12:1 1 200 "$reading" > "$file.part"
  mv "$file.part" "$file"
  echo "$reading: $(($(date +%s) - t0)) s, $(date -u +%FT%TZ)" >> "$out/progress.txt"
done
