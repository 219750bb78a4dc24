#!/usr/bin/env python3
"""What one Newton iteration of the full solve costs against its numeric factorization (issue 4's
target: at most 1.25x). Runs `sa map --mode full --report` on cases of ../shared/data (the same
cases as bench/map_benchmarks.py), checks each result with ../shared/tools/check_map.py, and
prints, per run, from the report's per-iteration records of the assembly stage:

  iteration / factorization   median over iterations 2.. of (iteration time + the mean callback
                              time per iteration) / that iteration's factorization time. The
                              first iteration is shown apart: it pays the first touch of the
                              factor's memory, which flatters it.
  phase totals                the sum of the phase times over the factorization's, as older
                              measurements computed it (first iteration included)
  ms per iteration            each phase's total over the iterations

  python3 bench/iteration_cost.py [--only stgc-3d,stretch] [--repeat 3]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

from map_benchmarks import ROOT, cases, diagonal_of_targets

PHASES = ['evaluate', 'project', 'assemble', 'factorize', 'solve', 'line_search', 'callbacks']


def run(a, case, work, index):
    out = os.path.join(work, '%s.%d%s' % (case['name'].replace('/', '_'), index,
                                          '.node' if case['dim'] == 3 else '.obj'))
    report = out + '.json'
    command = [a.sa, 'map'] + case['args'] + ['--mode', 'full', '--out', out, '--report', report,
                                              '--no-png', '--force', '--quiet']
    p = subprocess.run(command, capture_output=True, text=True)
    if p.returncode != 0 or not os.path.exists(report):
        return dict(case=case['name'], error='sa exit %d: %s' % (p.returncode, p.stderr.strip()[-300:]))
    rep = json.load(open(report))
    tol = 1e-6 * diagonal_of_targets(case['check'])
    c = subprocess.run([sys.executable, a.checker] + case['check'] + ['--result', out, '--tol', repr(tol)],
                       capture_output=True, text=True)
    try:
        verified = json.loads(c.stdout).get('ok', False)
    except json.JSONDecodeError:
        verified = False
    phases = rep['times']['newton_phases']
    rows = [r for r in rep['iterations'] if r['iteration'] > 0 and 'factorization_time' in r]
    n = len(rows)
    callbacks = phases['callbacks'] / n if n else 0.0
    ratios = [(r['iteration_time'] + callbacks) / r['factorization_time'] for r in rows]
    return dict(case=case['name'], iterations=n, verified=verified,
                factorization=statistics.median(r['factorization_time'] for r in rows[1:]),
                iteration=statistics.median(r['iteration_time'] + callbacks for r in rows[1:]),
                ratio=statistics.median(ratios[1:]), first=ratios[0],
                totals=sum(phases[k] for k in PHASES) / phases['factorize'],
                per_iteration={k: phases[k] / n for k in PHASES})


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--sa', default=os.path.join(ROOT, 'build', 'bin', 'sa'))
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'))
    ap.add_argument('--checker', default=os.path.join(ROOT, '..', 'shared', 'tools', 'check_map.py'))
    ap.add_argument('--only', default='stgc-3d,deform/stretch,param2d',
                    help='comma-separated parts of case names')
    ap.add_argument('--repeat', type=int, default=3, help='runs per case')
    a = ap.parse_args()

    work = tempfile.mkdtemp(prefix='sa-iteration-cost-')
    wanted = a.only.split(',')
    print('| case | run | iterations | factorization (ms) | iteration (ms) | iteration / '
          'factorization | first iteration | phase totals | ms per iteration: ' +
          ', '.join(PHASES) + ' | check_map.py |')
    print('|---|---:|---:|---:|---:|---:|---:|---:|---|:---|')
    for case in cases(a.data, ['tlc', 'deform']):
        if not any(w in case['name'] for w in wanted):
            continue
        for i in range(a.repeat):
            r = run(a, case, work, i)
            if 'error' in r:
                print('| %s | %d | %s |' % (case['name'], i + 1, r['error']))
                continue
            print('| %s | %d | %d | %.1f | %.1f | **%.3f** | %.3f | %.3f | %s | %s |' % (
                r['case'], i + 1, r['iterations'], 1e3 * r['factorization'], 1e3 * r['iteration'],
                r['ratio'], r['first'], r['totals'],
                ', '.join('%.2f' % (1e3 * r['per_iteration'][k]) for k in PHASES),
                'verified' if r['verified'] else 'NOT verified'), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
