#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Every fine triangulation (TOPCOM, streamed: never all
# held) of the degenerate sets and of random integer sets of 12 points.
# Each step writes one file of tallies and resumes where it stopped.
#
#   stream_topcom.sh OUTDIR [THREADS [STEP ...]]
#
# Steps (default: all, in this order):
#   grid223      the 2x2x3 grid, plain in 3 orders and the helper under all
#                36 readings in every order (93 runs per triangulation)
#   two_spheres  12 points on two concentric spheres, seeds 1-3, 93 runs each
#   random12     random integer sets of 12 points, seeds 1-3: plain and the
#                package's helper reading in 3 orders (6 runs each)
#   cube_face_centres  cube with centre and face centres, 93 runs each
#   cube_face_centres_package  the same set: plain and the package's helper
#                reading in 3 orders (6 runs each)
#   two_spheres_package  the two-spheres sets, seeds 1-3, 6 runs each
#   grid332      the 3x3x2 grid: plain and the package's helper in 3 orders
#                (123,182,774 triangulations: about 93 hours of one thread
#                here, laboratory/results/grid332.md)
#   random12all  random integer set of 12 points, seed 1, 93 runs each
set -euo pipefail
out=${1:?usage: stream_topcom.sh OUTDIR [THREADS [STEP ...]]}
threads=${2:-2}
shift $(($# < 2 ? $# : 2))
steps=${*:-grid223 two_spheres random12 cube_face_centres grid332 random12all}
bin=${EDGE_SWAP_LAB:-"$(cd "$(dirname "$0")/../.." && pwd)/build/bin/edge_swap_lab"}
mkdir -p "$out"
common=(--starts topcom --stream --max-cycles 200 --threads "$threads" --strategies plain,helper
        --orders storage,random,priority)
run() { # NAME ARGS...
  local name=$1
  shift
  local t0=$(date +%s)
  "$bin" experiment -o "$out/$name.jsonl" "${common[@]}" "$@" > "$out/$name.summary.txt" 2>> "$out/$name.log"
  echo "$name done in $(($(date +%s) - t0)) s: $(date -u +%FT%TZ)" >> "$out/progress.txt"
}
for step in $steps; do
  case $step in
    grid223) run grid223 --families grid-2x2x3 --sizes 12 --seeds 1 --readings all ;;
    two_spheres) run two_spheres --families two-spheres --sizes 12 --seeds 1-3 --readings all ;;
    cube_face_centres) run cube_face_centres --families cube-face-centres --sizes 15 --seeds 1 --readings all ;;
    cube_face_centres_package) run cube_face_centres_package --families cube-face-centres --sizes 15 --seeds 1 ;;
    two_spheres_package) run two_spheres_package --families two-spheres --sizes 12 --seeds 1-3 ;;
    random12) run random12 --families random-integer --sizes 12 --seeds 1-3 ;;
    grid332) run grid332 --families grid-3x3x2 --sizes 18 --seeds 1 ;;
    random12all) run random12all --families random-integer --sizes 12 --seeds 1 --readings all ;;
    *) echo "unknown step '$step'" >&2; exit 2 ;;
  esac
done
