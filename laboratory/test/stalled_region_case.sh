#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# laboratory/scripts/stalled_region_case.py (a ctest test): the stalled
# region of the 10^6-point run, its cells kept and the rest of its hull filled
# by TetGen, is a start the program accepts, the same as the kept case; bad
# input is exit 2 with no output file.
#
#   stalled_region_case.sh EDGE_SWAP_LAB SOURCE_DIR WORK_DIR
set -euo pipefail
edge_swap=${1:?usage: stalled_region_case.sh EDGE_SWAP_LAB SOURCE_DIR WORK_DIR}
source_dir=${2:?}
work=${3:?}
make_case=$source_dir/laboratory/scripts/stalled_region_case.py
# The folder unpacked from results/stall_helper_1e6.tar.xz.
region=${EDGE_SWAP_LAB_UNPACKED:-$source_dir/laboratory/results}/stall_helper_1e6
rm -rf "$work"
mkdir -p "$work"
fail() {
  echo "FAILED: $*" >&2
  exit 1
}

python3 "$make_case" "$region/stall_1000000.node" "$region/stall_1000000.ele" "$work/start.json" 1 1000 |
  grep -qF "931 points, 3304 cells of the region and 2524 filling the rest of the hull (3 of TetGen's 4 parts)" ||
  fail "the region's case: 931 points, 3304 + 2524 cells"
cmp -s "$work/start.json" "$region/stalled_region_start.json" || fail "not the kept stalled_region_start.json"
# The program reads it as a start (a triangulation of the hull) and runs it: one cycle.
"$edge_swap" replay "$work/start.json" --max-cycles 1 | grep -q '"valid":true' || fail "the start is not accepted"

# Bad input: exit 2, no output file.
bad() {
  local what=$1
  shift
  local status=0
  python3 "$make_case" "$@" "$work/bad.json" 2> "$work/error.txt" || status=$?
  [ $status = 2 ] || fail "$what: exit $status, not 2"
  [ ! -e "$work/bad.json" ] || fail "$what: an output file"
  [ -s "$work/error.txt" ] || fail "$what: no message"
}
bad "a missing file" "$work/none.node" "$region/stall_1000000.ele"
printf '2 3 0 0\n0 0 0 0\n' > "$work/short.node"
bad "fewer rows than the count" "$work/short.node" "$region/stall_1000000.ele"
printf '1 4 0\n0 0 1 2 3\n' > "$work/one.ele"
printf '4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 x\n' > "$work/nan.node"
bad "a coordinate that is not a number" "$work/nan.node" "$work/one.ele"
printf '4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 nan\n' > "$work/nan.node"
bad "a coordinate nan" "$work/nan.node" "$work/one.ele"
printf '4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 1 0 0\n' > "$work/twice.node"
bad "a point twice" "$work/twice.node" "$work/one.ele"
printf '1 4 0\n0 0 1 2 931\n' > "$work/range.ele"
bad "an index out of range" "$region/stall_1000000.node" "$work/range.ele"
printf '3 4 0\n0 0 1 2 3\n1 0 1 2 4\n2 0 1 2 5\n' > "$work/three.ele"
bad "a triangle in three cells" "$region/stall_1000000.node" "$work/three.ele"
echo "stalled region case: all checks passed"
