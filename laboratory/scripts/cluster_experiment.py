#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# An experiment of stream_and_certify_shard.sh in N shards, on a Slurm cluster,
# through GNU parallel (this machine, or a few over ssh), or here one shard after
# another; then the shards merged, their certificates set beside their streams,
# and the tables written.
#
#   cluster_experiment.py run OUTDIR SET N [--batch B] [--engine slurm|parallel|local]
#                         [--sbatch "OPTIONS"] [--jobs J] [--sshloginfile FILE]
#   cluster_experiment.py status OUTDIR
#   cluster_experiment.py merge OUTDIR     (Slurm's dependent job runs it)
#   cluster_experiment.py task OUTDIR I    (one shard: an array task or a parallel job)
#
# SET is random-integer:SIZE:S or family:NAME:SIZE:S (stream_and_certify_shard.sh); shard I
# is the blocks of B starts (4096 unless given) numbered I modulo N.
#
# `run` is idempotent: run again with the same arguments, it submits only the shards
# neither finished nor pending or running (a task that failed, was cancelled or
# preempted), and each resubmitted shard resumes where its files stop. With Slurm
# it submits them as one job array (a task a shard, one CPU each, job name
# edge_swap_lab.HASH.shards, HASH from OUTDIR's path) and a job that depends on
# every shard job (afterany) and runs `merge`; it cancels a merge job still
# pending from an earlier call, and returns at once. With parallel and local it
# runs the shards, then merges, and returns when all is done.
#
# OUTDIR gets
#   experiment.json    SET, N and B (a call with others is refused)
#   shard_I/           stream_and_certify_shard.sh's folder of shard I, and
#                      shard_I/finished once the shard's script ended (its exit
#                      status, seconds and verdict)
#   logs/shard_I.log   shard I's messages, every attempt's (and Slurm's)
#   logs/merge.log     the merge job's messages (Slurm)
#   readings.md        summarize_readings.py on every shard's tallies
#   certified_loops.md summarize_certified_loops.py on every shard's certification
#   against.md         certified_against_stream.py on all shards together
#   summary.md         the experiment, its shards' times and the three tables
#
# Exit status of `run` (parallel, local) and `merge`: 0 when every shard is finished
# and every reading agrees, with every run at the limit a certified loop or seen to
# end later; 1 when not; 2 for bad arguments (no OUTDIR made) or shards not
# finished (each named with its log). `run` with Slurm: 0 once submitted, 2 for bad
# arguments or a job the cluster refuses (tried with sbatch --test-only before OUTDIR is
# made). `task`: the shard script's status.
#
# Programs: EDGE_SWAP_LAB and EXPERIMENT_PRIORITY_LOOPS, else the build folder's.

import argparse
import hashlib
import json
import os
import re
import shlex
import shutil
import socket
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import summarize_readings  # noqa: E402

SHARD_SCRIPT = os.path.join(HERE, "stream_and_certify_shard.sh")
BUILD_BIN = os.path.normpath(os.path.join(HERE, "..", "..", "build", "bin"))
SET = re.compile(r"^(random-integer:[0-9]{1,9}:[0-9]{1,9}|family:[a-z0-9-]+:[0-9]{1,9}:[0-9]{1,9})$")
# Slurm states of a job that will still run, or is running.
ACTIVE = {"PENDING", "RUNNING", "CONFIGURING", "COMPLETING", "SUSPENDED", "REQUEUED", "REQUEUE_HOLD",
          "REQUEUE_FED", "RESIZING", "SIGNALING", "STAGE_OUT", "STOPPED", "RESV_DEL_HOLD"}


class Bad(Exception):
    """Bad arguments or a refused submission: exit 2 with the message."""


def programs():
    """The two programs the shard script runs, as absolute paths, so that a job on another
    machine of a shared file system finds them too."""
    found = {}
    for variable, name in (("EDGE_SWAP_LAB", "edge_swap_lab"), ("EXPERIMENT_PRIORITY_LOOPS", "experiment_priority_loops")):
        path = os.path.abspath(os.environ.get(variable, os.path.join(BUILD_BIN, name)))
        if not os.access(path, os.X_OK):
            raise Bad("%s is not an executable program: build the laboratory (laboratory/README.md) or set %s" %
                      (path, variable))
        found[variable] = path
    return found


def own_command(env, *words):
    """A shell command line that runs this script with WORDS (shell words, already quoted) and the
    programs in ENV."""
    return " ".join(["env"] + ["%s=%s" % (k, shlex.quote(v)) for k, v in sorted(env.items())] +
                    [shlex.quote(sys.executable), shlex.quote(os.path.abspath(__file__))] + list(words))


def task_command(outdir, shard, env):
    """The command line of one shard's task; shard may be a shell word such as $SLURM_ARRAY_TASK_ID."""
    return own_command(env, "task", shlex.quote(outdir), shard)


def read_experiment(outdir):
    path = os.path.join(outdir, "experiment.json")
    try:
        with open(path) as f:
            e = json.load(f)
        if not (isinstance(e, dict) and isinstance(e.get("set"), str) and SET.match(e["set"]) and
                type(e.get("shards")) is int and e["shards"] > 0 and type(e.get("batch")) is int and e["batch"] > 0):
            raise ValueError("not an experiment of this script")
        return e
    except (OSError, ValueError) as error:
        raise Bad("%s: %s (made by `cluster_experiment.py run`)" % (path, error))


def shards_text(n):
    return "%d shard%s" % (n, "" if n == 1 else "s")


def shard_dir(outdir, i):
    return os.path.join(outdir, "shard_%d" % i)


def log_path(outdir, i):
    return os.path.join(outdir, "logs", "shard_%d.log" % i)


def finished(outdir, i):
    """The shard's record once its script ended with 0 or 1, else None (a
    record that is not the task's, damaged or edited, counts as not finished:
    the shard runs again)."""
    try:
        with open(os.path.join(shard_dir(outdir, i), "finished")) as f:
            record = json.load(f)
    except (OSError, ValueError):
        return None
    if not isinstance(record, dict) or type(record.get("status")) is not int or record["status"] not in (0, 1):
        return None
    seconds = record.get("seconds")
    if type(seconds) not in (int, float) or not seconds >= 0 or not isinstance(record.get("verdict"), str):
        return None
    return record


def last_line(path):
    try:
        with open(path, errors="replace") as f:
            lines = [line.rstrip("\n") for line in f if line.strip()]
        return lines[-1] if lines else "(empty)"
    except OSError:
        return "(no log yet)"


def task(outdir, i):
    """Runs shard I: its messages appended to its log, a line on standard error saying how it ended."""
    e = read_experiment(outdir)
    if not 0 <= i < e["shards"]:
        raise Bad("shard %d: the experiment has shards 0 to %d" % (i, e["shards"] - 1))
    record_path = os.path.join(shard_dir(outdir, i), "finished")
    if os.path.exists(record_path):
        os.remove(record_path)
    os.makedirs(os.path.join(outdir, "logs"), exist_ok=True)
    log = log_path(outdir, i)
    start = time.time()
    with open(log, "a") as out:
        out.write("shard %d of %d, started %s on %s%s\n" % (
            i, e["shards"], time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime(start)), socket.gethostname(),
            ", Slurm job %s" % os.environ["SLURM_JOB_ID"] if "SLURM_JOB_ID" in os.environ else ""))
        out.flush()
        status = subprocess.run(["bash", SHARD_SCRIPT, shard_dir(outdir, i), e["set"], str(i), str(e["shards"]),
                                 str(e["batch"])], stdout=out, stderr=subprocess.STDOUT).returncode
        seconds = round(time.time() - start, 1)
        out.write("shard %d of %d ended with exit status %d after %s s\n" % (i, e["shards"], status, seconds))
    if status in (0, 1):
        verdict = last_line(os.path.join(shard_dir(outdir, i), "against.md"))
        with open(record_path + ".part", "w") as f:
            json.dump({"status": status, "seconds": seconds, "verdict": verdict}, f)
        os.replace(record_path + ".part", record_path)
        sys.stderr.write("shard %d of %d finished in %s s: %s\n" % (i, e["shards"], seconds, verdict))
    else:
        sys.stderr.write("shard %d of %d failed (exit status %d); its log: %s\n" % (i, e["shards"], status, log))
    return status


def run_summary(command, output):
    """Runs a summarizing script with its output to a file; returns its exit status."""
    with open(output, "w") as out:
        status = subprocess.run(command, stdout=out, stderr=subprocess.PIPE, text=True)
    if status.returncode not in (0, 1):
        raise Bad("%s failed (exit status %d): %s" % (os.path.basename(command[1]), status.returncode,
                                                      status.stderr.strip()))
    return status.returncode


def merge(outdir):
    """Checks that every shard finished, then writes the tables. The exit status as described above."""
    e = read_experiment(outdir)
    n = e["shards"]
    left = [i for i in range(n) if finished(outdir, i) is None]
    if left:
        for i in left:
            sys.stderr.write("shard %d of %d not finished; its log: %s (last line: %s)\n" % (
                i, n, log_path(outdir, i), last_line(log_path(outdir, i))))
        sys.stderr.write("%d of %d shards not finished: run the same `cluster_experiment.py run` again to "
                         "resubmit them\n" % (len(left), n))
        return 2
    python = sys.executable
    shards = [shard_dir(outdir, i) for i in range(n)]
    streams = [os.path.join(d, "stream.jsonl.xz") for d in shards]
    certified = [os.path.join(d, "certified") for d in shards]
    files = {name: os.path.join(outdir, name) for name in ("readings.md", "certified_loops.md", "against.md")}
    run_summary([python, os.path.join(HERE, "summarize_readings.py")] + streams, files["readings.md"])
    loops = run_summary([python, os.path.join(HERE, "summarize_certified_loops.py")] + certified,
                        files["certified_loops.md"])
    against = run_summary([python, os.path.join(HERE, "certified_against_stream.py"), "--stream"] + streams +
                          ["--certified"] + certified, files["against.md"])
    records = [finished(outdir, i) for i in range(n)]
    seconds = sum(r["seconds"] for r in records)
    verdict = last_line(files["against.md"])
    with open(os.path.join(outdir, "summary.md.part"), "w") as out:
        out.write("# %s in %s of blocks of %d starts\n\n" % (e["set"], shards_text(n), e["batch"]))
        out.write("Every fine triangulation (TOPCOM) under every reading and order, streamed; each fixed-order "
                  "run at the cycle limit traced and certified by the independent checker "
                  "(`stream_and_certify_shard.sh`).\n\n")
        out.write("- %s\n- the shards' scripts took %s s in all (%.2f core-hours); the longest %s s\n\n" % (
            verdict, round(seconds, 1), seconds / 3600, max(r["seconds"] for r in records)))
        for title, name in (("The streams' tallies", "readings.md"), ("The certified loops", "certified_loops.md"),
                            ("Certificates beside the streams", "against.md")):
            with open(files[name]) as f:
                out.write("## %s (`%s`)\n\n%s\n" % (title, name, f.read()))
    os.replace(os.path.join(outdir, "summary.md.part"), os.path.join(outdir, "summary.md"))
    print("%s: %s" % (os.path.join(outdir, "summary.md"), verdict))
    return 0 if loops == 0 and against == 0 else 1


def squeue_jobs(name):
    """(array task index or None, job id, job name, state) of this experiment's jobs in Slurm's queue."""
    command = ["squeue", "--noheader", "--array", "--name", "%s.shards,%s.merge" % (name, name),
               "--format", "%i|%j|%T|%K"]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        raise Bad("squeue failed (exit status %d): %s" % (result.returncode, result.stderr.strip()))
    jobs = []
    for line in result.stdout.splitlines():
        fields = line.strip().split("|")
        if len(fields) != 4:
            continue
        job, job_name, state, index = fields
        jobs.append((int(index) if index.isdigit() else None, job.split("_")[0], job_name, state.split()[0]))
    return jobs


def sbatch(arguments):
    result = subprocess.run(["sbatch", "--parsable"] + arguments, capture_output=True, text=True)
    if result.returncode != 0:
        raise Bad("sbatch refused the job (exit status %d): %s" % (result.returncode, result.stderr.strip()))
    return result.stdout.strip().split(";")[0]


def array_list(numbers):
    """'0-3,7' for [0, 1, 2, 3, 7]: Slurm's --array list."""
    return summarize_readings.ranges(numbers).replace(" ", "")


def run_slurm(outdir, e, env, extra):
    name = "edge_swap_lab.%s" % hashlib.sha1(outdir.encode()).hexdigest()[:12]
    jobs = squeue_jobs(name)
    active = {index for index, _, job_name, state in jobs if job_name.endswith(".shards") and state in ACTIVE}
    active_jobs = sorted({job for _, job, job_name, state in jobs if job_name.endswith(".shards") and state in ACTIVE})
    pending_merges = sorted({job for _, job, job_name, state in jobs if job_name.endswith(".merge") and state == "PENDING"})
    n = e["shards"]
    done = [i for i in range(n) if finished(outdir, i) is not None]
    todo = [i for i in range(n) if i not in done and i not in active]
    print("%s: %d of %d shards finished, %d pending or running (%s)" % (
        outdir, len(done), n, len(active), array_list(sorted(active)) or "none"))
    if not todo and not active_jobs and os.path.exists(os.path.join(outdir, "summary.md")):
        print("every shard finished and merged: %s" % os.path.join(outdir, "summary.md"))
        return 0
    if pending_merges:
        subprocess.run(["scancel"] + pending_merges, check=False)
    if todo:
        array = sbatch(["--job-name", name + ".shards", "--array", array_list(todo), "--ntasks", "1", "--cpus-per-task", "1",
                        "--output", os.path.join(outdir, "logs", "shard_%a.log"), "--open-mode", "append"] + extra +
                       ["--wrap", task_command(outdir, "$SLURM_ARRAY_TASK_ID", env)])
        active_jobs.append(array)
        print("submitted shards %s as job array %s; logs: %s" % (array_list(todo), array, os.path.join(outdir, "logs")))
    dependency = ["--dependency", "afterany:" + ":".join(active_jobs)] if active_jobs else []
    merge_job = sbatch(["--job-name", name + ".merge", "--ntasks", "1", "--cpus-per-task", "1",
                        "--output", os.path.join(outdir, "logs", "merge.log"), "--open-mode", "append"] + dependency +
                       extra + ["--wrap", own_command(env, "merge", shlex.quote(outdir))])
    print("submitted the merge as job %s%s: it writes %s (log: %s)" % (
        merge_job, " after jobs " + ", ".join(active_jobs) if active_jobs else "",
        os.path.join(outdir, "summary.md"), os.path.join(outdir, "logs", "merge.log")))
    return 0


def run_here(outdir, e, env, engine, jobs, sshloginfile):
    n = e["shards"]
    todo = [i for i in range(n) if finished(outdir, i) is None]
    print("%s: %d of %d shards finished, %d to run" % (outdir, n - len(todo), n, len(todo)), flush=True)
    if todo and engine == "parallel":
        command = ["parallel", "--jobs", str(jobs)]
        if sshloginfile:
            command += ["--sshloginfile", sshloginfile]
        command += [task_command(outdir, "{}", env), ":::"] + [str(i) for i in todo]
        subprocess.run(command)  # each failed task says so; merge names the shards left
    elif todo:
        os.environ.update(env)
        for i in todo:
            task(outdir, i)
    return merge(outdir)


def run(a):
    if not SET.match(a.set):
        raise Bad("SET is random-integer:SIZE:S or family:NAME:SIZE:S, not '%s'" % a.set)
    for value, what in ((a.shards, "N"), (a.batch, "--batch")):
        if not re.match(r"^[0-9]{1,9}$", value) or int(value) == 0:
            raise Bad("%s is a whole number above 0, not '%s'" % (what, value))
    if not re.match(r"^[0-9]{1,4}$", a.jobs) or int(a.jobs) == 0:
        raise Bad("--jobs is a whole number above 0, not '%s'" % a.jobs)
    tool = {"slurm": "sbatch", "parallel": "parallel"}.get(a.engine)
    if tool and not shutil.which(tool):
        raise Bad("--engine %s: %s is not on PATH (Debian: apt-get install %s)" % (
            a.engine, tool, "slurm-client" if tool == "sbatch" else "parallel"))
    if a.sshloginfile and a.engine != "parallel":
        raise Bad("--sshloginfile is an option of --engine parallel")
    if a.sbatch and a.engine != "slurm":
        raise Bad("--sbatch is an option of --engine slurm")
    try:
        extra = shlex.split(a.sbatch or "")
    except ValueError as error:
        raise Bad("--sbatch '%s': %s" % (a.sbatch, error))
    env = programs()
    if a.engine == "slurm":  # the cluster answers and takes the options, before anything is made
        test = subprocess.run(["sbatch", "--test-only"] + extra + ["--wrap", "true"], capture_output=True, text=True)
        if test.returncode != 0:
            raise Bad("sbatch --test-only%s refused the job (exit status %d): %s" % (
                "".join(" " + shlex.quote(x) for x in extra), test.returncode, test.stderr.strip()))
    outdir = os.path.abspath(a.outdir)
    wanted = {"set": a.set, "shards": int(a.shards), "batch": int(a.batch)}
    if os.path.exists(os.path.join(outdir, "experiment.json")):
        e = read_experiment(outdir)
        if e != wanted:
            raise Bad("%s holds %s in %s of blocks of %d, not %s in %s of blocks of %d: give the same arguments "
                      "or another OUTDIR" % (outdir, e["set"], shards_text(e["shards"]), e["batch"], a.set,
                                             shards_text(wanted["shards"]), wanted["batch"]))
    elif os.path.exists(outdir) and os.listdir(outdir):
        raise Bad("%s is not empty and holds no experiment.json: give a new OUTDIR" % outdir)
    else:
        os.makedirs(outdir, exist_ok=True)
        with open(os.path.join(outdir, "experiment.json"), "w") as f:
            json.dump(wanted, f)
            f.write("\n")
    os.makedirs(os.path.join(outdir, "logs"), exist_ok=True)
    if a.engine == "slurm":
        return run_slurm(outdir, wanted, env, extra)
    return run_here(outdir, wanted, env, a.engine, a.jobs, a.sshloginfile)


def status(outdir):
    e = read_experiment(outdir)
    for i in range(e["shards"]):
        record = finished(outdir, i)
        print("shard %d: %s" % (i, "finished in %s s: %s" % (record["seconds"], record["verdict"]) if record else
                                "not finished; log %s: %s" % (log_path(outdir, i), last_line(log_path(outdir, i)))))
    return 0


def main():
    parser = argparse.ArgumentParser(prog="cluster_experiment.py",
                                     description="An experiment of stream_and_certify_shard.sh in shards.")
    commands = parser.add_subparsers(dest="command", required=True)
    r = commands.add_parser("run", help="run or submit the shards not finished, then merge")
    r.add_argument("outdir", metavar="OUTDIR")
    r.add_argument("set", metavar="SET")
    r.add_argument("shards", metavar="N")
    r.add_argument("--batch", default="4096", metavar="B")
    r.add_argument("--engine", choices=("slurm", "parallel", "local"), default="slurm")
    r.add_argument("--sbatch", metavar="OPTIONS", help="more sbatch options for every job, as one argument")
    r.add_argument("--jobs", default="2", metavar="J", help="parallel jobs (a host) with --engine parallel")
    r.add_argument("--sshloginfile", metavar="FILE", help="GNU parallel's hosts, with --engine parallel")
    for name in ("status", "merge"):
        commands.add_parser(name).add_argument("outdir", metavar="OUTDIR")
    t = commands.add_parser("task")
    t.add_argument("outdir", metavar="OUTDIR")
    t.add_argument("shard", metavar="I")
    a = parser.parse_args()
    try:
        if a.command == "run":
            return run(a)
        outdir = os.path.abspath(a.outdir)
        if a.command == "status":
            return status(outdir)
        if a.command == "merge":
            return merge(outdir)
        if not re.match(r"^[0-9]{1,9}$", a.shard):
            raise Bad("I is a whole number, not '%s'" % a.shard)
        return task(outdir, int(a.shard))
    except Bad as error:
        sys.stderr.write("cluster_experiment.py: %s\n" % error)
        return 2


if __name__ == "__main__":
    sys.exit(main())
