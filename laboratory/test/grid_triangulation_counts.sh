#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# laboratory/scripts/count_grid_triangulations.py (a ctest test): TOPCOM
# counting with the grid's symmetries gives the same number of fine
# triangulations as TOPCOM counting without them (so the generators are the
# grid's symmetries, in point_families.h's point order), the cube's 74, and bad
# arguments exit 2.
#
#   grid_triangulation_counts.sh SOURCE_DIR
set -euo pipefail
script=${1:?usage: grid_triangulation_counts.sh SOURCE_DIR}/laboratory/scripts/count_grid_triangulations.py
fail() {
  echo "FAILED: $*" >&2
  exit 1
}
field() { python3 -c "import json,sys; print(json.load(sys.stdin)['$1'])"; }
without_symmetries() { # the grid's points, in grid()'s order, with no symmetry given
  python3 -c "
import itertools, sys
n = [int(a) for a in sys.argv[1:]]
print('[' + ','.join('[%d,%d,%d,1]' % p for p in itertools.product(*map(range, n))) + ']')" "$@" |
    topcom-points2nallfinetriangs 2> /dev/null | tail -1
}
for g in "2 2 2" "2 2 3" "3 2 2" "2 3 2"; do
  read -ra n <<< "$g"
  with=$(python3 "$script" "${n[@]}" | field triangulations)
  plain=$(without_symmetries "${n[@]}")
  [ "$with" = "$plain" ] || fail "grid $g: $with with symmetries, $plain without"
done
[ "$(python3 "$script" 2 2 2 | field triangulations)" = 74 ] || fail "the cube has 74 triangulations"
[ "$(python3 "$script" 2 2 3 | field symmetries)" = 16 ] || fail "the 2x2x3 grid has 16 symmetries"
for args in "1 2 2" "2 2" "5 5 5" "2 2 x"; do
  read -ra a <<< "$args"
  set +e
  python3 "$script" "${a[@]}" > /dev/null 2>&1
  rc=$?
  set -e
  [ $rc -eq 2 ] || fail "'$args' exited $rc, not 2"
done
echo "count_grid_triangulations.py: the counts with symmetries are TOPCOM's without them"
