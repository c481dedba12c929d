#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Is there a trap on fewer points? Traps are starts from which no order at all
brings the helper strategy to CGAL's triangulation. Every fine triangulation
(TOPCOM) of each point set is scanned for them by
experiment_adversarial_orders --traps, under each of READINGS.

    scan_traps.py subsets CASE SIZE READINGS OUTDIR [MAX_TRIANGULATIONS [KEEP]]
    scan_traps.py cap|slab N SEEDS READINGS OUTDIR [MAX_TRIANGULATIONS]

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
    fail('usage: scan_traps.py subsets CASE SIZE READINGS OUTDIR [MAX_TRIANGULATIONS [KEEP]]\n'
         '       scan_traps.py cap|slab N SEEDS READINGS OUTDIR [MAX_TRIANGULATIONS]')


def main():
    sets, out, readings, most = point_sets(sys.argv)
    whole(most, 'MAX_TRIANGULATIONS', 1)
    os.makedirs(out, exist_ok=True)
    summary = os.path.join(out, 'summary.txt')
    done = set()
    if os.path.exists(summary):
        with open(summary) as f:
            done = {line.split(' ')[0] for line in f if line.strip()}
    for name, points in sets:
        if name in done:
            continue
        case_file = os.path.join(out, f'{name}.json')
        certificate = os.path.join(out, f'{name}.trap.json')
        with open(case_file, 'w') as f:
            json.dump({'points': points, 'start': 'placing', 'strategy': 'helper', 'order': 'random', 'seed': 1}, f)
        results = []
        for reading in readings.split('+'):
            began = time.time()
            run = subprocess.run([PROGRAM, '--traps', 'topcom:' + case_file, reading, most, certificate + '.part'],
                                 capture_output=True, text=True)
            if run.returncode != 0:
                os.remove(case_file)
                fail(f'{name}, {reading}: the program ended with {run.returncode}: {run.stderr.strip()}')
            lines = run.stdout.splitlines()
            results.append(f'{name} {lines[-1]}; {time.time() - began:.0f} s\n')
            for t in lines:
                if t.startswith('start '):
                    print(f'{name}: {t}', flush=True)
            if os.path.exists(certificate + '.part'):
                os.replace(certificate + '.part', certificate)
        with open(summary, 'a') as f:  # all readings at once: a set stopped midway is scanned again
            f.writelines(results)
        os.remove(case_file)
    totals = {}
    pattern = re.compile(r'^\S+ reading (\S+): (\d+) starts, .* traps (\d+)(;|$)')
    with open(summary) as f:
        for line in f:
            m = pattern.match(line)
            if not m:
                fail(f'{summary}: a line not written by this script: {line.strip()!r}')
            t = totals.setdefault(m.group(1), [0, 0, 0])
            t[0] += 1
            t[1] += int(m.group(2))
            t[2] += int(m.group(3))
    print('reading sets starts traps')
    for reading, (count, starts, trapped) in sorted(totals.items()):
        print(reading, count, starts, trapped)


if __name__ == '__main__':
    main()
