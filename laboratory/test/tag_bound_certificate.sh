#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# check_tag_bounds.py (a ctest test): it certifies the kept certificates of the
# 25- and 12-point traps, refuses altered ones (exit 1, naming what fails) and
# unreadable files (exit 2), and survives mutated files.
#
#   tag_bound_certificate.sh SOURCE_DIR WORK_DIR [FUZZ_SEED]
set -euo pipefail
source_dir=${1:?usage: tag_bound_certificate.sh SOURCE_DIR WORK_DIR [FUZZ_SEED]}
work=${2:?}
fuzz_seed=${3:-1}
here=$source_dir/laboratory/test
checker=$source_dir/laboratory/checker/check_tag_bounds.py
kept=$here/fixtures/trap_25_points_tag_bounds.json
rm -rf "$work"
mkdir -p "$work"
fail() {
  echo "FAILED: $*" >&2
  exit 1
}

for certified in "trap_25_points_tag_bounds.json 168" "trap_12_points_tag_bounds.json 2"; do
  set -- $certified
  python3 "$checker" "$here/fixtures/$1" > "$work/out.txt" || fail "$1: exit $?"
  grep -qF "certified: $2 triangulations, closed under every visit; none is CGAL's triangulation; no state ends a run under no-swap-no-tag" "$work/out.txt" ||
    fail "$1: $(cat "$work/out.txt")"
done

# expect STATUS MESSAGE FILE: the checker exits STATUS and says MESSAGE.
expect() {
  local status=0
  python3 "$checker" "$3" > /dev/null 2> "$work/error.txt" || status=$?
  [ "$status" = "$1" ] || fail "$3: exit $status, not $1: $(cat "$work/error.txt")"
  grep -qF -- "$2" "$work/error.txt" || fail "$3: no '$2' in: $(cat "$work/error.txt")"
  grep -qF -- "$3: " "$work/error.txt" || fail "$3: the message does not name the file"
  ! grep -q Traceback "$work/error.txt" || fail "$3: a traceback"
}
# alter NAME MESSAGE PYTHON: the kept certificate changed by PYTHON (on c), then exit 1 with MESSAGE.
alter() {
  python3 - "$kept" "$work/$1.json" "$3" <<'EOF'
import json, sys
c = json.load(open(sys.argv[1]))
exec(sys.argv[3])
json.dump(c, open(sys.argv[2], "w"))
EOF
  expect 1 "$2" "$work/$1.json"
}
start_index='next(k for k, t in enumerate(c["triangulations"]) if sorted(t["cells"]) == sorted(c["start"]))'
alter missing "its flip makes a triangulation that is not listed" \
  "s = $start_index; del c['triangulations'][(s + 1) % len(c['triangulations'])]"
alter tag_dropped "are beyond the bound" \
  "t = next(t for t in c['triangulations'] if t['tag_bound']); t['tag_bound'].pop()"
alter start_moved "the start is not one of the triangulations" "c['start'] = c['start'][1:]"
alter point_moved "not certified" "c['points'][0][0] += 0.5"
printf '%s\n' '{"format":"Edge_swapping_3 tag-bound certificate","version":1,"reading":"until-destroyed,pass-over,no-swap","points":[[0,0,0],[1,0,0],[0,1,0],[0,0,1]],"start":[[0,1,2,3]],"triangulations":[{"cells":[[0,1,2,3]],"tag_bound":[]}]}' > "$work/delaunay.json"
expect 1 "triangulation 0 is CGAL's triangulation" "$work/delaunay.json"

# Unreadable: exit 2, naming the file and the problem.
bad() {
  printf '%s\n' "$2" > "$work/$1.json"
  expect 2 "$3" "$work/$1.json"
}
head='"format":"Edge_swapping_3 tag-bound certificate","version":1'
four='[[0,0,0],[1,0,0],[0,1,0],[0,0,1]]'
bad not_json '{"format": ' "not JSON"
bad other_format '{"format":"Edge_swapping_3 visit trace","version":1}' "not a version 1 tag-bound certificate"
bad version_true '{"format":"Edge_swapping_3 tag-bound certificate","version":true}' "not a version 1 tag-bound certificate"
bad no_points "{$head,\"start\":[],\"triangulations\":[]}" "'points' is not a list"
bad nan "{$head,\"points\":[[NaN,0,0],[1,0,0],[0,1,0],[0,0,1]],\"start\":[],\"triangulations\":[]}" "point 0 has a coordinate that is not finite"
bad huge "{$head,\"points\":[[1e300,0,0],[1,0,0],[0,1,0],[0,0,1]],\"start\":[],\"triangulations\":[]}" "point 0 has a coordinate that is not finite or beyond 1e30"
bad three_points "{$head,\"points\":[[0,0,0],[1,0,0],[0,1,0]],\"start\":[],\"triangulations\":[]}" "fewer than four points"
bad same_points "{$head,\"points\":[[0,0,0],[1,0,0],[0,1,0],[0,1,0]],\"start\":[],\"triangulations\":[]}" "two points are the same"
bad out_of_range "{$head,\"points\":$four,\"start\":[[0,1,2,4]],\"triangulations\":[]}" "four point numbers below 4"
bad repeated "{$head,\"points\":$four,\"start\":[[0,1,1,3]],\"triangulations\":[]}" "a cell with a repeated point"
bad twice "{$head,\"points\":$four,\"start\":[[0,1,2,3],[3,2,1,0]],\"triangulations\":[]}" "a cell listed twice"
bad no_reading "{$head,\"points\":$four,\"start\":[[0,1,2,3]],\"triangulations\":[]}" "'reading' is not a reading whose tags go"
bad never_cleared "{$head,\"reading\":\"never-cleared,pass-over,no-swap\",\"points\":$four,\"start\":[[0,1,2,3]],\"triangulations\":[]}" \
  "'reading' is not a reading whose tags go"
bad bad_made "{$head,\"reading\":\"until-destroyed,pass-over,no-swap,sometimes\",\"points\":$four,\"start\":[[0,1,2,3]],\"triangulations\":[]}" \
  "'reading' is not a reading whose tags go"
bad bound_outside "{$head,\"points\":[[0,0,0],[1,0,0],[0,1,0],[0,0,1],[1,1,1]],\"start\":[[0,1,2,3]],\"triangulations\":[{\"cells\":[[0,1,2,3]],\"tag_bound\":[[0,1,2,4]]}]}" "holds a cell that is not one of its cells"
bad not_object "{$head,\"points\":$four,\"start\":[[0,1,2,3]],\"triangulations\":[7]}" "triangulation 0 is not an object"
expect 2 "cannot read it" "$work/none.json"
status=0
python3 "$checker" > /dev/null 2>&1 || status=$?
[ $status = 2 ] || fail "no argument: exit $status, not 2"

# Mutated files, in one process: every outcome is certified, wrong or
# unreadable, never another exception.
python3 - "$here" "$kept" "$fuzz_seed" <<'EOF'
import json, os, random, sys, tempfile
sys.path.insert(0, sys.argv[1] + "/../checker")
import check_tag_bounds as ctb
seed = int(sys.argv[3])
print(f"fuzz seed {seed}")
rng = random.Random(seed)
kept = json.load(open(sys.argv[2]))
small = {"format": kept["format"], "version": 1, "points": kept["points"][:8], "start": [[0, 1, 2, 3]],
         "triangulations": [{"cells": [[0, 1, 2, 3]], "tag_bound": []}]}
values = [None, True, -1, 0, 3, 10**40, 1e308, "x", [], {}, [0, 1, 2], float("nan")]
outcomes = {}
def run(text):
    try:
        json.loads(text)
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            f.write(text)
        try:
            points, start, bounds = ctb.read_certificate(f.name)
            ctb.check(points, start, bounds)
            return "certified"
        finally:
            os.unlink(f.name)
    except (ctb.Unreadable, json.JSONDecodeError):
        return "unreadable"
    except ctb.Wrong:
        return "wrong"
def mutate(node):
    # One change somewhere in the tree: a value replaced, an entry dropped or doubled.
    if isinstance(node, list) and node and rng.random() < 0.7:
        k = rng.randrange(len(node))
        r = rng.random()
        if r < 0.3: node[k] = rng.choice(values)
        elif r < 0.5: del node[k]
        elif r < 0.6: node.append(node[k])
        else: mutate(node[k])
    elif isinstance(node, dict) and node:
        k = rng.choice(list(node))
        if rng.random() < 0.3: node[k] = rng.choice(values)
        elif rng.random() < 0.1: del node[k]
        else: mutate(node[k])
for n in range(300):
    c = json.loads(json.dumps(small))
    mutate(c)
    text = json.dumps(c)
    if rng.random() < 0.3:  # and some bytes
        b = bytearray(text, "utf-8")
        for _ in range(rng.randint(1, 4)):
            b[rng.randrange(len(b))] = rng.randrange(32, 127)
        text = b.decode("utf-8")
    outcome = run(text)
    outcomes[outcome] = outcomes.get(outcome, 0) + 1
print("fuzz outcomes", outcomes)
EOF
echo "tag_bound_certificate: passed"
