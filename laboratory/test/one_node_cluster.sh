#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# cluster_experiment.py on a real Slurm, a cluster of one node started here (a
# ctest test): munged, slurmctld and slurmd in the foreground with a generated
# configuration (localhost, 2 CPUs, process tracking without cgroups). Every
# fine triangulation of 9 random integer points (set 5: 1,164 starts, blocks of
# 8) in 6 shards as a job array; one task is cancelled while it runs, the merge
# job names it, the same command resubmits it alone; the merged tallies, runs and
# certified loops must equal those of the experiment run as one shard in one local
# process. Then the same through GNU parallel, with one shard's programs killed.
# The daemons are stopped at the end, whatever happened; where Slurm cannot start,
# the test fails and says why.
#
#   one_node_cluster.sh SOURCE_DIR WORK_DIR EDGE_SWAP_LAB EXPERIMENT_PRIORITY_LOOPS
set -euo pipefail
source_dir=${1:?usage: one_node_cluster.sh SOURCE_DIR WORK_DIR EDGE_SWAP_LAB EXPERIMENT_PRIORITY_LOOPS}
work=${2:?}
export EDGE_SWAP_LAB=${3:?} EXPERIMENT_PRIORITY_LOOPS=${4:?}
script=$source_dir/laboratory/scripts/cluster_experiment.py
set_name=random-integer:9:5
shards=6
fail() {
  echo "FAILED: $*" >&2
  exit 1
}
for program in munged slurmctld slurmd sbatch squeue scancel sinfo parallel python3; do
  command -v $program > /dev/null ||
    fail "$program is not on PATH: install slurmctld slurmd slurm-client munge parallel (the extended test command does)"
done
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
cluster=$work/cluster
mkdir -p "$cluster/state" "$cluster/spool"
chmod 755 "$work" "$cluster" # munged refuses a socket in a folder not everyone may enter

# --- The cluster ---------------------------------------------------------------------------
daemons=()
stop_cluster() {
  local status=$?
  set +e
  [ -z "${SLURM_CONF:-}" ] || scancel --user "$(id -un)" 2> /dev/null
  if [ ${#daemons[@]} -gt 0 ]; then
    kill "${daemons[@]}" 2> /dev/null
    for _ in $(seq 100); do # up to 10 s; an ended daemon is a zombie until waited for
      states=$(ps -o stat= -p "$(IFS=,; echo "${daemons[*]}")")
      grep -qv '^Z' <<< "$states" || break
      sleep 0.1
    done
    kill -9 "${daemons[@]}" 2> /dev/null
    wait "${daemons[@]}" 2> /dev/null
  fi
  pkill -9 -f "$work/" 2> /dev/null # anything a job left (slurmstepd, the shards' programs)
  sleep 0.5
  if pgrep -af "$work/" > /dev/null; then
    echo "FAILED: processes left running:" >&2
    pgrep -af "$work/" >&2
    status=1
  fi
  exit $status
}
trap stop_cluster EXIT

node=$(hostname -s 2> /dev/null || uname -n)
cpus=$(($(nproc) < 2 ? $(nproc) : 2))
read -r controller_port node_port < <(python3 -c '
import socket
ports = []
sockets = [socket.socket() for _ in range(2)]
for s in sockets:
    s.bind(("127.0.0.1", 0))
    ports.append(s.getsockname()[1])
print(*ports)')
dd if=/dev/urandom of="$cluster/munge.key" bs=1024 count=1 status=none
chmod 400 "$cluster/munge.key"
cat > "$cluster/slurm.conf" << EOF
ClusterName=edgeswaplab
SlurmctldHost=$node(127.0.0.1)
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
AuthInfo=socket=$cluster/munge.socket
CredType=cred/munge
SlurmctldPort=$controller_port
SlurmdPort=$node_port
StateSaveLocation=$cluster/state
SlurmdSpoolDir=$cluster/spool
SlurmctldPidFile=$cluster/slurmctld.pid
SlurmdPidFile=$cluster/slurmd.pid
SlurmctldLogFile=$cluster/slurmctld.log
SlurmdLogFile=$cluster/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=lab Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$cluster/slurm.conf
cannot_start() {
  echo "Slurm did not start: $*" >&2
  for log in munged.out slurmctld.out slurmd.out slurmctld.log slurmd.log; do
    [ -f "$cluster/$log" ] && { echo "--- $log" >&2; tail -n 15 "$cluster/$log" >&2; }
  done
  fail "a one-node Slurm cluster could not be started here (above: the daemons' last messages)"
}
munged --foreground --socket="$cluster/munge.socket" --key-file="$cluster/munge.key" --pid-file="$cluster/munged.pid" \
  --seed-file="$cluster/munged.seed" --log-file="$cluster/munged.log" > "$cluster/munged.out" 2>&1 &
daemons+=($!)
for _ in $(seq 50); do [ -S "$cluster/munge.socket" ] && break; sleep 0.1; done
[ -S "$cluster/munge.socket" ] || cannot_start "munged made no socket"
slurmctld -D -i -f "$SLURM_CONF" > "$cluster/slurmctld.out" 2>&1 &
daemons+=($!)
slurmd -D -f "$SLURM_CONF" > "$cluster/slurmd.out" 2>&1 &
daemons+=($!)
for _ in $(seq 150); do
  [ "$(sinfo --noheader --format %T 2> /dev/null)" = idle ] && break
  sleep 0.2
done
[ "$(sinfo --noheader --format %T 2> /dev/null)" = idle ] ||
  cannot_start "the node is not idle after 30 s (sinfo: $(sinfo --noheader 2>&1 | head -n 1))"
echo "a cluster of one node ($node, $cpus CPUs) is up"

queue_empty() { # seconds: waits until no job is in the queue
  for _ in $(seq $(($1 * 5))); do
    [ -z "$(squeue --noheader)" ] && return 0
    sleep 0.2
  done
  fail "jobs still in the queue after $1 s: $(squeue --noheader | head -n 5)"
}
# What must equal the one-process run: the tallies (not the count of files they were read
# from), the certified loops (not the seconds column, nor which shards were added up), the
# certificates beside the streams, and every run that did not end on CGAL's triangulation
# (its start, strategy, order, reading, ending, cycles and swaps; not its seconds).
runs() {
  python3 - "$1"/shard_*/stream.jsonl << 'EOF'
import json, sys
lines = []
for path in sys.argv[1:]:
    for line in open(path):
        record = json.loads(line)
        if "key" in record:
            record.pop("seconds")
            lines.append(json.dumps(record, sort_keys=True))
print("\n".join(sorted(lines)))
EOF
}
same_as_local() { # OUTDIR
  cmp -s <(grep -Ev ' instances in [0-9]+ files$|^shards of ' "$work/local/readings.md") \
         <(grep -Ev ' instances in [0-9]+ files$|^shards of ' "$1/readings.md") || fail "$1: the tallies differ from the local run's"
  local strip='s/ [0-9,]+ \|$/ |/; s/, [0-9,]+ s$//; / of [0-9]+ shards \(/d'
  cmp -s <(sed -E "$strip" "$work/local/certified_loops.md") <(sed -E "$strip" "$1/certified_loops.md") ||
    fail "$1: the certified loops differ from the local run's"
  cmp -s "$work/local/against.md" "$1/against.md" || fail "$1: the certificates beside the streams differ"
  cmp -s <(runs "$work/local") <(runs "$1") || fail "$1: the runs not ending on CGAL's triangulation differ"
}

# --- The experiment in one local process ---------------------------------------------------------
python3 "$script" run "$work/local" $set_name 1 --batch 8 --engine local > "$work/local.out" 2>&1 ||
  fail "the local run: exit $? ($(tail -n 2 "$work/local.out"))"
grep -q '^- 36 of 36 readings agree; the stream has 6,626 fixed-order runs at the limit$' "$work/local/summary.md" ||
  fail "the local run: not the 6,626 runs at the limit, all certified"
[ "$(runs "$work/local" | wc -l)" = 6652 ] || fail "the local run: not 6,652 runs off CGAL's triangulation"

# --- Slurm: an array of 6 tasks, one cancelled while it runs --------------------------------------
out=$work/slurm
status=0
python3 "$script" run "$out" $set_name $shards --sbatch=--partition=none > /dev/null 2> "$work/bad.txt" || status=$?
[ $status = 2 ] && grep -q "sbatch --test-only --partition=none refused the job" "$work/bad.txt" && [ ! -e "$out" ] ||
  fail "a partition the cluster does not have: exit $status, $(cat "$work/bad.txt"), not exit 2 and no folder"
python3 "$script" run "$out" $set_name $shards --batch 8 > "$work/submit1.txt" 2>&1 || fail "sbatch: $(cat "$work/submit1.txt")"
cat "$work/submit1.txt"
grep -q "^submitted shards 0-5 as job array [0-9]*" "$work/submit1.txt" || fail "the 6 shards were not submitted as one array"
array=$(sed -nE 's/^submitted shards 0-5 as job array ([0-9]+).*/\1/p' "$work/submit1.txt")
# A shard is cancelled once its stream has written a block's tally and before its script
# ended; if one ends between the look and the cancel, the next is taken.
killed=
for _ in $(seq 600); do
  for i in $(squeue --noheader --array --states RUNNING --format %K 2> /dev/null); do
    [[ $i =~ ^[0-9]+$ ]] || continue
    if grep -q '"tally"' "$out/shard_$i/stream.jsonl" 2> /dev/null && [ ! -e "$out/shard_$i/finished" ]; then
      scancel "${array}_$i"
      for _ in $(seq 100); do
        [[ $'\n'$(squeue --noheader --array --format %i)$'\n' == *$'\n'"${array}_$i"$'\n'* ]] || break
        sleep 0.1
      done
      if [ ! -e "$out/shard_$i/finished" ]; then killed=$i; fi
      break
    fi
  done
  [ -n "$killed" ] && break
  [ -n "$(squeue --noheader)" ] || break
  sleep 0.05
done
[ -n "$killed" ] || fail "no shard could be cancelled while it ran"
echo "cancelled shard $killed of $shards while it ran"
queue_empty 300
grep -q "^shard $killed of $shards not finished; its log: $out/logs/shard_$killed.log" "$out/logs/merge.log" ||
  fail "the merge job does not name the cancelled shard and its log: $(cat "$out/logs/merge.log")"
[ ! -e "$out/summary.md" ] || fail "a summary was written with a shard missing"
grep -q "CANCELLED" "$out/logs/shard_$killed.log" || fail "the cancelled shard's log does not say so"
python3 "$script" status "$out" > "$work/status.txt"
grep -q "^shard $killed: not finished; log $out/logs/shard_$killed.log" "$work/status.txt" ||
  fail "status does not name the cancelled shard: $(cat "$work/status.txt")"

python3 "$script" run "$out" $set_name $shards --batch 8 > "$work/submit2.txt" 2>&1 || fail "resubmitting: $(cat "$work/submit2.txt")"
cat "$work/submit2.txt"
grep -q "^$out: 5 of 6 shards finished, 0 pending or running" "$work/submit2.txt" &&
  grep -q "^submitted shards $killed as job array" "$work/submit2.txt" || fail "the cancelled shard alone was not resubmitted"
queue_empty 300
[ -s "$out/summary.md" ] || fail "no summary after the resubmission: $(tail -n 3 "$out/logs/merge.log")"
[ "$(grep -c '^shard [0-9] of 6, started' "$out/logs/shard_$killed.log")" = 2 ] || fail "shard $killed did not run twice"
same_as_local "$out"
python3 "$script" run "$out" $set_name $shards --batch 8 > "$work/submit3.txt" 2>&1
grep -q "^every shard finished and merged" "$work/submit3.txt" && [ -z "$(squeue --noheader)" ] ||
  fail "a third call on a finished experiment submitted jobs"
echo "Slurm: the merged results equal the local run's"

# --- GNU parallel: 6 shards, 2 at a time, one shard's programs killed -----------------------------
out=$work/parallel
python3 "$script" run "$out" $set_name $shards --batch 8 --engine parallel --jobs 2 > "$work/parallel1.txt" 2>&1 &
runner=$!
killed=
for _ in $(seq 600); do
  for i in $(seq 0 $((shards - 1))); do
    if grep -q '"tally"' "$out/shard_$i/stream.jsonl" 2> /dev/null && [ ! -e "$out/shard_$i/finished" ] &&
       pkill -KILL -f "$out/shard_$i/" 2> /dev/null; then
      killed=$i
      break
    fi
  done
  [ -n "$killed" ] && break
  kill -0 $runner 2> /dev/null || break
  sleep 0.05
done
status=0
wait $runner || status=$?
[ -n "$killed" ] || fail "no shard's programs could be killed while they ran"
echo "killed the programs of shard $killed of $shards while they ran"
[ $status = 2 ] || fail "with a shard killed: exit $status, not 2"
grep -q "^shard $killed of $shards failed (exit status [0-9]*); its log: $out/logs/shard_$killed.log" "$work/parallel1.txt" &&
  grep -q "^shard $killed of $shards not finished; its log: $out/logs/shard_$killed.log" "$work/parallel1.txt" ||
  fail "the killed shard and its log are not named: $(cat "$work/parallel1.txt")"
python3 "$script" run "$out" $set_name $shards --batch 8 --engine parallel --jobs 2 > "$work/parallel2.txt" 2>&1 ||
  fail "parallel, the second call: exit $? ($(tail -n 3 "$work/parallel2.txt"))"
grep -q "^$out: 5 of 6 shards finished, 1 to run" "$work/parallel2.txt" || fail "parallel did not run the killed shard alone"
same_as_local "$out"
echo "GNU parallel: the merged results equal the local run's"

# --- Bad arguments: exit 2, a message, no OUTDIR made ---------------------------------------------
for bad in "random-integer:9 6|SET is" "random-integer:9:5 0|N is a whole number above 0" \
           "random-integer:9:5 6 --batch x|--batch is" "random-integer:9:5 6 --jobs 0|--jobs is" \
           "random-integer:9:5 6 --engine local --sbatch=-p|--sbatch is an option of --engine slurm" \
           "random-integer:9:5 6 --sshloginfile h|--sshloginfile is an option of --engine parallel"; do
  status=0
  # shellcheck disable=SC2086 # the arguments, split
  python3 "$script" run "$work/bad" ${bad%|*} > /dev/null 2> "$work/bad.txt" || status=$?
  [ $status = 2 ] && grep -qF -- "${bad#*|}" "$work/bad.txt" && [ ! -e "$work/bad" ] ||
    fail "'${bad%|*}': exit $status, '$(cat "$work/bad.txt")', not exit 2 with '${bad#*|}' and no folder"
done
status=0
python3 "$script" run "$work/local" $set_name 3 --engine local > /dev/null 2> "$work/bad.txt" || status=$?
[ $status = 2 ] && grep -q "holds random-integer:9:5 in 1 shard of blocks of 8, not random-integer:9:5 in 3 shards of blocks of 4096" "$work/bad.txt" ||
  fail "another N for an experiment's folder: exit $status, $(cat "$work/bad.txt")"
echo "one_node_cluster.sh: all checks passed"
