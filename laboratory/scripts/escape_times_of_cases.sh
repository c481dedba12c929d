#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Escape times of the helper strategy in random order from every saved case
# in a directory (`edge_swap_lab experiment --cases DIR`), each case its own seeds:
# the n-th case in name order (n from 0) runs seeds n*SEEDS+1 to n*SEEDS+SEEDS.
# Runs of one seed from different starts that meet in one state go on as one
# run, so shared seeds would not give independent samples (conjectures.md,
# "Seeds per start").
#
#   escape_times_of_cases.sh CASES_DIR SEEDS MAX_CYCLES OUT [THREADS]
#
# Appends experiment_escape_times' lines to OUT; a case whose source is already
# in OUT is skipped, so a stopped run resumes. escape_histogram.py reads OUT.
set -euo pipefail
usage="usage: escape_times_of_cases.sh CASES_DIR SEEDS MAX_CYCLES OUT [THREADS]"
dir=${1:?$usage}
seeds=${2:?$usage}
max_cycles=${3:?$usage}
out=${4:?$usage}
threads=${5:-2}
for number in "$seeds" "$max_cycles" "$threads"; do
  [[ $number =~ ^[1-9][0-9]{0,8}$ ]] || { echo "escape_times_of_cases.sh: '$number' is not a whole number from 1 to 999999999" >&2; exit 2; }
done
[ -d "$dir" ] || { echo "escape_times_of_cases.sh: $dir is not a directory" >&2; exit 2; }
bin=${EXPERIMENT_ESCAPE_TIMES:-"$(cd "$(dirname "$0")/../.." && pwd)/build/bin/experiment_escape_times"}
mapfile -t cases < <(find "$dir" -maxdepth 1 -name '*.json' | LC_ALL=C sort)
[ ${#cases[@]} -gt 0 ] || { echo "escape_times_of_cases.sh: no case file (*.json) in $dir" >&2; exit 2; }
# The seeds must stay below 2^32, the tool's seed range.
if (( ${#cases[@]} * seeds > 4294967295 )); then
  echo "escape_times_of_cases.sh: ${#cases[@]} cases of $seeds seeds pass 2^32 seeds" >&2
  exit 2
fi
touch "$out"
for n in "${!cases[@]}"; do
  case=${cases[$n]}
  grep -qF "\"source\":\"$case\"" "$out" && continue
  # One case at a time into a temporary file: a stopped case leaves no part in OUT.
  "$bin" "$case" $((n * seeds + 1)) $((n * seeds + seeds)) "$max_cycles" "$threads" > "$out.part"
  cat "$out.part" >> "$out"
  rm -f "$out.part"
done
