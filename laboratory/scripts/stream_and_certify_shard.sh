#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# One task of a cluster job array: shard I of N of every
# fine triangulation of a point set (TOPCOM, streamed, never all held), each run
# under every reading and order (edge_swap_lab experiment --stream --readings all:
# plain swapping in 3 orders and the helper in 90 reading-and-order pairs, 93
# runs a start); then each fixed-order run of the shard still going at cycle 200
# traced and certified by the independent checker (certify_fixed_order_loops.sh);
# then the two set side by side, reading by reading (certified_against_stream.py).
# The shard is the blocks of BATCH starts numbered I modulo N (BATCH 4096 unless
# given), the same blocks for both programs. Each step resumes where it
# stopped, so the task can be run again after a stop (or a preemption).
#
#   stream_and_certify_shard.sh OUTDIR SET I N [BATCH]
#
# SET is random-integer:SIZE:S (the laboratory's SIZE random integer points of
# set S) or family:NAME:SIZE:S (point_families.h); S also seeds the face
# orders: the fixed order is the priority of seed S, as in the laboratory's streams.
# OUTDIR gets
#   stream.jsonl       the stream: a line for each run not ending on CGAL's
#                      triangulation, and a tally line for each block
#   stream.jsonl.xz    its first line and its tally lines, compressed: what
#                      laboratory/results/random12all/ keeps of a shard
#   stream.log         edge_swap's messages, each attempt's after the last
#   certified/         one file per reading (certify_fixed_order_loops.sh)
#   against.md         the comparison
# Exit 0 when every reading of the stream is certified with the stream's runs and
# runs at the limit, and each run at the limit is a loop or seen to end later;
# 1 when not; 2 for bad arguments (no OUTDIR made) or a step that failed.
#
# cluster_experiment.py runs the N tasks of a set as a Slurm job array (or through
# GNU parallel) and merges them: set 3 of the 12 random points in 64 tasks is
#   python3 laboratory/scripts/cluster_experiment.py run out/set3 random-integer:12:3 64
set -euo pipefail
usage="usage: stream_and_certify_shard.sh OUTDIR SET I N [BATCH]  (SET: random-integer:SIZE:S or family:NAME:SIZE:S)"
bad() {
  echo "stream_and_certify_shard.sh: $*" >&2
  echo "$usage" >&2
  exit 2
}
[ $# = 4 ] || [ $# = 5 ] || bad "4 or 5 arguments, not $#"
out=$1
set_name=$2
shard=$3
shards=$4
batch=${5:-4096}
number() { [[ $1 =~ ^[0-9]{1,9}$ ]]; } # a whole number below 10^9
number "$shard" && number "$shards" && [ $((10#$shards)) -gt 0 ] && [ $((10#$shard)) -lt $((10#$shards)) ] ||
  bad "I and N are whole numbers with I < N, not '$shard' and '$shards'"
number "$batch" && [ $((10#$batch)) -gt 0 ] || bad "BATCH is a whole number above 0, not '$batch'"
IFS=: read -r -a part <<< "$set_name"
if [ "${part[0]}" = random-integer ] && [ ${#part[@]} = 3 ]; then
  family=random-integer size=${part[1]} seed=${part[2]}
elif [ "${part[0]}" = family ] && [ ${#part[@]} = 4 ]; then
  family=${part[1]} size=${part[2]} seed=${part[3]}
else
  bad "SET is random-integer:SIZE:S or family:NAME:SIZE:S, not '$set_name'"
fi
number "$size" && number "$seed" || bad "SIZE and S in '$set_name' are whole numbers"
here=$(cd "$(dirname "$0")" && pwd)
edge_swap=${EDGE_SWAP_LAB:-"$here/../../build/bin/edge_swap_lab"}

made=0
[ -d "$out" ] || made=1
mkdir -p "$out"
# 1. The stream (edge_swap checks the set and its options before it writes anything). A
# finished stream is not resumed: that would have TOPCOM list the set again to find nothing left.
# The log grows by each attempt (its last line gives the attempt's time).
status=0
logged=$(stat -c %s "$out/stream.log" 2> /dev/null || echo 0)
grep -q '"complete":true' "$out/stream.jsonl" 2> /dev/null ||
  "$edge_swap" experiment -o "$out/stream.jsonl" --starts topcom --stream --stream-batch "$batch" \
    --shard "$shard/$shards" --max-cycles 200 --threads 1 --strategies plain,helper \
    --orders storage,random,priority --families "$family" --sizes "$size" --seeds "$seed" --readings all \
    > "$out/stream.summary.txt" 2>> "$out/stream.log" || status=$?
if [ $status != 0 ]; then
  tail -c +$((logged + 1)) "$out/stream.log" >&2
  if [ $made = 1 ] && [ ! -s "$out/stream.jsonl" ]; then rm -rf "$out"; fi
  exit 2
fi
grep -E '^\{"(stream|tally)"' "$out/stream.jsonl" | xz -c > "$out/stream.jsonl.xz"
# 2. The fixed-order runs at the limit, traced and certified (a reading done is not run again).
bash "$here/certify_fixed_order_loops.sh" "$out/certified" "$set_name" "$seed-$seed" \
  --shard "$shard/$shards" --stream-batch "$batch" || exit 2
# 3. Side by side: exit 0 when they agree, 1 when not.
python3 "$here/certified_against_stream.py" --stream "$out/stream.jsonl" --certified "$out/certified" \
  > "$out/against.md" || exit $?
tail -n 1 "$out/against.md"
