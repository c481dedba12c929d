#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes again the last states of the 40 random-order runs on 1,000 cospherical
# points that had not ended by cycle 20,000 (conjectures.md, "Escape times"):
# each seed run to cycle 20,000 by experiment_escape_times, its last
# triangulation saved as a case and compressed to OUT/seed_S.json.xz, then
# every file checked byte for byte against
# laboratory/results/unended_cospherical_1000_states.sha256. The runs are
# exact and deterministic; about 4 minutes a seed on one core (each seed runs
# twice: once to find it unended, once to save its state).
#
#   unended_cospherical_states.sh OUT [JOBS]     (JOBS at a time, default 2)
#
# experiment_escape_times is taken from $EXPERIMENT_ESCAPE_TIMES, else
# build/bin. Exit 0 when every state is made and checks, 1 otherwise.
set -euo pipefail
out=${1:?usage: unended_cospherical_states.sh OUT [JOBS]}
jobs=${2:-2}
here=$(cd "$(dirname "$0")" && pwd)
sums=$here/../results/unended_cospherical_1000_states.sha256
program=${EXPERIMENT_ESCAPE_TIMES:-$here/../../build/bin/experiment_escape_times}
[ -x "$program" ] || { echo "unended_cospherical_states.sh: no $program (build the laboratory first)" >&2; exit 2; }
mkdir -p "$out"
seeds=$(sed -E 's/.*seed_([0-9]+)\.json\.xz$/\1/' "$sums")
export program out
# shellcheck disable=SC2016 # expanded by the inner shell
printf '%s\n' $seeds | xargs -P "$jobs" -I{} sh -c '
  s={}
  [ -s "$out/seed_$s.json.xz" ] && exit 0
  dir="$out/run_$s"
  mkdir -p "$dir"
  "$program" cospherical:1000:1 "$s" "$s" 20000 1 "$dir" > "$dir/line.jsonl"
  xz -9 -c "$dir/unended_seed_$s.json" > "$out/seed_$s.json.xz.partial"
  mv "$out/seed_$s.json.xz.partial" "$out/seed_$s.json.xz"
  rm -rf "$dir"'
cd "$out" && sha256sum -c "$sums"
