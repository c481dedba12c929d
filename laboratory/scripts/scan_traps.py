#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Is there a trap on fewer points? Traps are starts from which no order at all
brings the helper strategy to CGAL's triangulation. Every fine triangulation
(TOPCOM) of each point set is scanned for them by
experiment_adversarial_orders --traps, under each of READINGS.

    scan_traps.py subsets CASE SIZE READINGS OUTDIR [MAX_TRIANGULATIONS [KEEP]] [--shard I/N]
    scan_traps.py cap|slab N SEEDS READINGS OUTDIR [MAX_TRIANGULATIONS] [--shard I/N]
    scan_traps.py total OUTDIR...

subsets: every subset of SIZE of a case file's points (integer coordinates,
which TOPCOM reads exactly); KEEP (point numbers joined by ',') keeps only the
subsets that hold those points. cap and slab: random sets of N integer points,
one per seed of SEEDS (FIRST-LAST), from Python's random.Random(seed):
  cap   uniform on the cap of angular radius 0.15 of the sphere of radius 10^6
        centred at the origin, around the x axis, rounded: nearly cospherical
        and nearly flat;
  slab  uniform in the box [0, 1500] x [0, 10^5] x [0, 10^5]: nearly flat,
        1.5% thick, as the 12-point trap (shrunk from the 10^6-point run).
READINGS is a reading, or several joined by '+'. Each set writes one line per
reading to OUTDIR/summary.txt (the set, then the program's summary line) and,
when it holds a trap, OUTDIR/<set>.trap.json, the certificate of its smallest
one (of the last reading that has one), which check_tag_bounds.py checks. A set
already in the summary is skipped, so a stopped scan resumes. At the end it
prints, per reading, the sets, starts and traps.

With --shard I/N each set's starts numbered I modulo N (in TOPCOM's order) are
scanned (experiment_adversarial_orders --traps ... --shard I/N; a trap's
certificate is then <set>.shardIofN.trap.json): N shards, each in its own OUTDIR (on any machines: a Slurm array or GNU parallel), scan every
start once. `total` adds up the summaries of OUTDIRs: a set counts when it was
scanned whole or in all N of its shards; the others are listed as incomplete.
"""
import itertools
import json
import math
import os
import random
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROGRAM = os.environ.get('EXPERIMENT_ADVERSARIAL_ORDERS',
                         os.path.join(HERE, '..', '..', 'build', 'bin', 'experiment_adversarial_orders'))


def fail(message):
    print('scan_traps.py: ' + message, file=sys.stderr)
    sys.exit(2)


def whole(text, what, least=0):
    if not text.isdigit() or int(text) < least:
        fail(f'{what} is a whole number of at least {least}, not {text!r}')
    return int(text)


def cap_points(n, seed):
    rng, points = random.Random(seed), set()
    while len(points) < n:
        c = rng.uniform(math.cos(0.15), 1.0)
        phi = rng.uniform(0, 2 * math.pi)
        s = math.sqrt(1 - c * c)
        points.add((round(1e6 * c), round(1e6 * s * math.cos(phi)), round(1e6 * s * math.sin(phi))))
    return sorted(points)


def slab_points(n, seed):
    rng, points = random.Random(seed), set()
    while len(points) < n:
        points.add((rng.randint(0, 1500), rng.randint(0, 100000), rng.randint(0, 100000)))
    return sorted(points)


def shard_option(argv):
    """argv without a trailing --shard I/N, and the shard's ' I/N' (or '')."""
    if len(argv) < 3 or argv[-2] != '--shard':
        return argv, ''
    m = re.fullmatch(r'(\d{1,9})/(\d{1,9})', argv[-1])
    if not m or int(m.group(1)) >= int(m.group(2)):
        fail(f'--shard takes I/N, with whole numbers I < N, not {argv[-1]!r}')
    return argv[:-2], f'{int(m.group(1))}/{int(m.group(2))}'


def point_sets(argv):
    """The named point sets of the command line, and OUTDIR, READINGS, MAX."""
    mode = argv[1] if len(argv) > 1 else ''
    if mode == 'subsets' and len(argv) in (6, 7, 8):
        case_file, size_text, readings, out = argv[2:6]
        most = argv[6] if len(argv) > 6 else '100000'
        try:
            with open(case_file) as f:
                points = json.load(f)['points']
            if not isinstance(points, list):
                raise TypeError('"points" is not a list')
        except (OSError, ValueError, KeyError, TypeError) as e:
            fail(f'{case_file}: not a case file with "points": {e}')
        size = whole(size_text, 'SIZE', 5)
        if size > len(points):
            fail(f'SIZE is at most {len(points)}, the points of {case_file}, not {size}')
        keep = {whole(w, 'a point number of KEEP') for w in filter(None, (argv[7] if len(argv) > 7 else '').split(','))}
        if any(k >= len(points) for k in keep):
            fail(f'KEEP names point numbers from 0 to {len(points) - 1}')
        sets = (('-'.join(map(str, s)), [points[i] for i in s])
                for s in itertools.combinations(range(len(points)), size) if keep <= set(s))
        return sets, out, readings, most
    if mode in ('cap', 'slab') and len(argv) in (6, 7):
        n = whole(argv[2], 'N', 5)
        if n > 64:  # TOPCOM could not list every triangulation of more anyway
            fail(f'N is at most 64, not {n}')
        m = re.fullmatch(r'(\d+)-(\d+)', argv[3])
        if not m or int(m.group(1)) > int(m.group(2)):
            fail(f'SEEDS is FIRST-LAST, not {argv[3]!r}')
        make = cap_points if mode == 'cap' else slab_points
        sets = ((f'{mode}_{n}_{seed}', [list(map(float, p)) for p in make(n, seed)])
                for seed in range(int(m.group(1)), int(m.group(2)) + 1))
        return sets, argv[5], argv[4], argv[6] if len(argv) > 6 else '100000'
    fail('usage: scan_traps.py subsets CASE SIZE READINGS OUTDIR [MAX_TRIANGULATIONS [KEEP]] [--shard I/N]\n'
         '       scan_traps.py cap|slab N SEEDS READINGS OUTDIR [MAX_TRIANGULATIONS] [--shard I/N]\n'
         '       scan_traps.py total OUTDIR...')


LINE = re.compile(r'^(\S+)(?: shard (\d+)/(\d+))? reading (\S+): (\d+) starts, .* traps (\d+)(;|$)')


def print_totals(summaries):
    """Per reading, the sets scanned whole (or in all their shards), their starts and traps."""
    parts = {}  # (set, reading) -> {shard count: {shard: (starts, traps)}}
    for summary in summaries:
        try:
            with open(summary) as f:
                lines = f.read().splitlines()
        except OSError as e:
            fail(f'{summary}: cannot read it: {e.strerror}')
        for number, line in enumerate(lines, 1):
            m = LINE.match(line)
            if not m:
                fail(f'{summary}, line {number}: a line not written by this script: {line.strip()!r}')
            name, shard, shards, reading = m.group(1), int(m.group(2) or 0), int(m.group(3) or 1), m.group(4)
            got = parts.setdefault((name, reading), {}).setdefault(shards, {})
            if shard in got:
                fail(f'{summary}, line {number}: {name}, {reading}, shard {shard}/{shards} is counted twice')
            got[shard] = (int(m.group(5)), int(m.group(6)))
    totals, incomplete = {}, []
    for (name, reading), by_count in sorted(parts.items()):
        whole_scans = [got for shards, got in by_count.items() if len(got) == shards]
        if not whole_scans:
            incomplete.append(f'{name} {reading}: ' + ', '.join(
                f'{len(got)} of {shards} shards' for shards, got in sorted(by_count.items())))
            continue
        t = totals.setdefault(reading, [0, 0, 0])
        t[0] += 1
        t[1] += sum(starts for starts, _ in whole_scans[0].values())
        t[2] += sum(traps for _, traps in whole_scans[0].values())
    print('reading sets starts traps')
    for reading, (count, starts, trapped) in sorted(totals.items()):
        print(reading, count, starts, trapped)
    for line in incomplete:
        print('incomplete: ' + line)


def main():
    if len(sys.argv) > 1 and sys.argv[1] == 'total':
        if len(sys.argv) < 3:
            fail('usage: scan_traps.py total OUTDIR...')
        print_totals([os.path.join(d, 'summary.txt') for d in sys.argv[2:]])
        return
    argv, shard = shard_option(sys.argv)
    sets, out, readings, most = point_sets(argv)
    whole(most, 'MAX_TRIANGULATIONS', 1)
    try:
        os.makedirs(out, exist_ok=True)
    except OSError as e:
        fail(f'OUTDIR {out}: cannot make it a directory: {e.strerror}')
    summary = os.path.join(out, 'summary.txt')
    label = f' shard {shard}' if shard else ''  # after the set's name in its summary lines
    done = set()
    if os.path.exists(summary):
        with open(summary) as f:
            done = {m.group(1) + (f' shard {m.group(2)}/{m.group(3)}' if m.group(2) else '')
                    for m in map(LINE.match, f) if m}
    for name, points in sets:
        if name + label in done:
            continue
        stem = name + ('.shard' + shard.replace('/', 'of') if shard else '')
        case_file = os.path.join(out, f'{stem}.json')
        certificate = os.path.join(out, f'{stem}.trap.json')
        with open(case_file, 'w') as f:
            json.dump({'points': points, 'start': 'placing', 'strategy': 'helper', 'order': 'random', 'seed': 1}, f)
        results = []
        for reading in readings.split('+'):
            began = time.time()
            run = subprocess.run([PROGRAM, '--traps', 'topcom:' + case_file, reading, most, certificate + '.part']
                                 + (['--shard', shard] if shard else []), capture_output=True, text=True)
            if run.returncode != 0:
                os.remove(case_file)
                fail(f'{name}, {reading}: the program ended with {run.returncode}: {run.stderr.strip()}')
            lines = run.stdout.splitlines()
            results.append(f'{name}{label} {lines[-1]}; {time.time() - began:.0f} s\n')
            for t in lines:
                if t.startswith('start '):
                    print(f'{name}: {t}', flush=True)
            if os.path.exists(certificate + '.part'):
                os.replace(certificate + '.part', certificate)
        with open(summary, 'a') as f:  # all readings at once: a set stopped midway is scanned again
            f.writelines(results)
        os.remove(case_file)
    print_totals([summary])


if __name__ == '__main__':
    main()
