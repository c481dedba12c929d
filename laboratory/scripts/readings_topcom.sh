#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Every reading of Algorithm 4 under every face order, from every fine
# triangulation (TOPCOM) of 10 random integer sets each of 6 to 10 points:
# plain swapping in 3 orders and the helper in 90 (reading, order) pairs (the
# 18 same-cycle readings have no storage order), at most 200 cycles. About
# 11.7 million instances, in 12 shards (one file each, so that each summary
# fits in memory); a stopped run resumes where it stopped.
#
#   readings_topcom.sh OUTDIR [THREADS [SHARD ...]]
#
# (the shards listed, default 0 to 11: two processes with disjoint lists share the work)
#
# Then: laboratory/scripts/summarize_readings.py OUTDIR/shard_*.jsonl
set -euo pipefail
out=${1:?usage: readings_topcom.sh OUTDIR [THREADS [SHARD ...]]}
threads=${2:-1}
shift $(($# < 2 ? $# : 2))
shards=${*:-$(seq 0 11)}
bin="$(cd "$(dirname "$0")/../.." && pwd)/build/bin/edge_swap_lab"
mkdir -p "$out"
for i in $shards; do
  "$bin" experiment -o "$out/shard_$i.jsonl" --families random-integer --sizes 6,7,8,9,10 --seeds 1-10 \
    --starts topcom --strategies plain,helper --orders storage,random,priority --readings all \
    --max-cycles 200 --shard "$i/12" --threads "$threads" > "$out/shard_$i.summary.txt" 2> "$out/shard_$i.log"
  echo "shard $i done: $(date -u +%FT%TZ)" >> "$out/progress.txt"
done
