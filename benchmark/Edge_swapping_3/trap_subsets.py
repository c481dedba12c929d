#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Is there a trap on fewer points? Every fine triangulation (TOPCOM) of every
subset of SIZE points of a case's points is scanned for traps, starts from
which no order at all brings the helper strategy to CGAL's triangulation
(experiment_adversarial_orders --traps, under each of READINGS).

    trap_subsets.py CASE SIZE READINGS OUTDIR [MAX_TRIANGULATIONS [KEEP]]

CASE is a case file whose points have integer coordinates (TOPCOM reads them
exactly); READINGS a reading, or several joined by '+'. Each subset writes one
line to OUTDIR/summary.txt (its points, then the program's summary line per
reading) and, when it holds a trap, OUTDIR/subset_<points>.trap.json, the
certificate of its smallest one (of the last reading that has one), which
check_tag_bounds.py checks. KEEP (point numbers joined by ',') scans only the
subsets that hold those points. A subset already in the summary is skipped, so a stopped scan resumes. At the end it
prints, per reading, the subsets, starts and traps.
"""
import itertools
import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PROGRAM = os.environ.get('EXPERIMENT_ADVERSARIAL_ORDERS',
                         os.path.join(HERE, '..', '..', 'build', 'bin', 'experiment_adversarial_orders'))


def fail(message):
    print('trap_subsets.py: ' + message, file=sys.stderr)
    sys.exit(2)


def main():
    if len(sys.argv) not in (5, 6, 7):
        fail('usage: trap_subsets.py CASE SIZE READINGS OUTDIR [MAX_TRIANGULATIONS [KEEP]]')
    case_file, size_text, readings, out = sys.argv[1:5]
    most = sys.argv[5] if len(sys.argv) > 5 else '100000'
    keep_text = sys.argv[6] if len(sys.argv) > 6 else ''
    try:
        with open(case_file) as f:
            case = json.load(f)
        points = case['points']
    except (OSError, ValueError, KeyError, TypeError) as e:
        fail(f'{case_file}: not a case file with "points": {e}')
    if not size_text.isdigit() or not 5 <= int(size_text) <= len(points):
        fail(f'SIZE is a whole number from 5 to {len(points)}, not {size_text!r}')
    size = int(size_text)
    if not most.isdigit() or int(most) == 0:
        fail(f'MAX_TRIANGULATIONS is a whole number above 0, not {most!r}')
    keep = set()
    for word in filter(None, keep_text.split(',')):
        if not word.isdigit() or int(word) >= len(points):
            fail(f'KEEP names point numbers from 0 to {len(points) - 1}, not {word!r}')
        keep.add(int(word))
    os.makedirs(out, exist_ok=True)
    summary = os.path.join(out, 'summary.txt')
    done = set()
    if os.path.exists(summary):
        with open(summary) as f:
            done = {line.split(' ')[0] for line in f if line.strip()}
    for subset in itertools.combinations(range(len(points)), size):
        name = '-'.join(map(str, subset))
        if name in done or not keep <= set(subset):
            continue
        sub_case = {'points': [points[i] for i in subset], 'start': 'placing', 'strategy': 'helper',
                    'order': 'random', 'seed': 1}
        sub_file = os.path.join(out, f'subset_{name}.json')
        certificate = os.path.join(out, f'subset_{name}.trap.json')
        with open(sub_file, 'w') as f:
            json.dump(sub_case, f)
        results = []
        for reading in readings.split('+'):
            began = time.time()
            run = subprocess.run([PROGRAM, '--traps', 'topcom:' + sub_file, reading, most, certificate + '.part'],
                                 capture_output=True, text=True)
            if run.returncode != 0:
                fail(f'subset {name}, {reading}: the program ended with {run.returncode}: {run.stderr.strip()}')
            lines = run.stdout.splitlines()
            results.append(f'{name} {lines[-1]}; {time.time() - began:.0f} s\n')
            for t in lines:
                if t.startswith('start '):
                    print(f'subset {name}: {t}', flush=True)
            if os.path.exists(certificate + '.part'):
                os.replace(certificate + '.part', certificate)
        with open(summary, 'a') as f: # all readings at once: a stopped subset is done again
            f.writelines(results)
        os.remove(sub_file)
    totals = {}
    pattern = re.compile(r'^\S+ reading (\S+): (\d+) starts, .* traps (\d+);')
    with open(summary) as f:
        for line in f:
            m = pattern.match(line)
            if not m:
                fail(f'{summary}: a line not written by this script: {line.strip()!r}')
            t = totals.setdefault(m.group(1), [0, 0, 0])
            t[0] += 1
            t[1] += int(m.group(2))
            t[2] += int(m.group(3))
    print('reading subsets starts traps')
    for reading, (subsets, starts, trapped) in sorted(totals.items()):
        print(reading, subsets, starts, trapped)


if __name__ == '__main__':
    main()
