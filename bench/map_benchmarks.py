#!/usr/bin/env python3
"""Runs `sa map` on the published untangling problems and 3D deformation problems of
../shared/data, checks every result with the independent checker ../shared/tools/check_map.py,
and prints a markdown table: elements, inverted before and after, handle error, delta_con and
delta_iso (max / area-weighted mean), iterations, wall time and peak memory of each run.

Cases:
  tlc/<name>        the plain-text problem (rest, initial map, handles) as published
                    (armadillo-598: the Locally Injective Mappings benchmark's hard class);
                    tlc/infeasible-star has no solution and must be diagnosed before optimizing
  deform/<name>     the rest shape with only the handle vertices moved to their positions in
                    <name>_init.node (the handles stay at those targets)
  untwist-twisted   deform/untwist with its whole _init.node as the initial map (the handles of
                    untwist do not move, so deform/untwist alone is the rest shape itself)
  gen/<name>        problems written by build/bin/bench_generate_problem
                    (tests/fixtures/generated_problems.h), feasible by construction: the fixed-boundary
                    hard class (every boundary vertex a handle at a twisted or bent and flattened
                    position, the interior tangled) and large deformations by handle slabs

  python3 bench/map_benchmarks.py [--cases tlc,deform,generated] [--timeout 600]
                                  [--write docs/performance.md]

With --write, the table replaces the section between the markers
<!-- map-benchmarks:begin --> and <!-- map-benchmarks:end --> of that file, with the command
and the date. Extra arguments after -- go to every `sa map` run.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from bench_common import fmt, run_measured, write_section

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


# The generated cases: name, generator arguments, extra sa arguments.
GENERATED = [
    ('gen/box-twist-flat', ['--grid', '6', '6', '16', '--deformation', 'twist', '--amount', '2',
                            '--noise', '1', '--flatten', '0.02', '--seed', '1'], []),
    ('gen/box-bend-flat', ['--grid', '6', '6', '16', '--deformation', 'bend', '--amount', '2',
                           '--noise', '1', '--flatten', '0.05', '--seed', '2'], []),
    ('gen/hand-twist', ['--mesh', '{data}/tet/hand.mesh', '--deformation', 'twist', '--amount', '1',
                        '--noise', '1', '--seed', '3'], []),
    ('gen/hand-twist-flat', ['--mesh', '{data}/tet/hand.mesh', '--deformation', 'twist',
                             '--amount', '1', '--noise', '1', '--flatten', '0.03', '--seed', '4'],
     []),
    ('gen/bar-twist-slabs', ['--kind', 'slabs', '--grid', '16', '16', '64', '--deformation', 'twist',
                             '--amount', '3.14159', '--slab', '0.05'], ['--distortion', 'isometric']),
    ('gen/bar-bend-slabs', ['--kind', 'slabs', '--grid', '16', '16', '64', '--deformation', 'bend',
                            '--amount', '3', '--slab', '0.05'], ['--distortion', 'isometric']),
]


def generated_cases(data, generator, work):
    out = []
    for name, args, extra in GENERATED:
        path = os.path.join(work, name.replace('/', '_') + '.txt')
        if not os.path.exists(path):
            r = subprocess.run([generator] + [x.format(data=data) for x in args] + ['--out', path],
                               capture_output=True, text=True)
            if r.returncode != 0:
                print('  generator failed for %s: %s' % (name, r.stderr.strip()), file=sys.stderr)
                continue
        out.append(dict(name=name, dim=3, args=['--rest', path] + extra, check=['--rest', path]))
    return out


def cases(data, which, generator=None, work=None):
    out = []
    if 'tlc' in which:
        for name in ['stgc-2d', 'sea-2d', 'param2d', 'cube', 'stgc-3d', 'armadillo-598',
                     'infeasible-star']:
            d = os.path.join(data, 'tlc', name)
            out.append(dict(name='tlc/' + name,
                            dim=3 if name in ('cube', 'stgc-3d', 'armadillo-598',
                                              'infeasible-star') else 2,
                            args=['--rest', os.path.join(d, 'input')],
                            check=['--rest', os.path.join(d, 'input')]))
    if 'deform' in which:
        for name in ['untwist', 'stretch', 'botijo', 'rabbit']:
            d = os.path.join(data, 'deform', name)
            rest, init = os.path.join(d, name + '_rest.node'), os.path.join(d, name + '_init.node')
            handles = os.path.join(d, name + '_handles.txt')
            common = ['--handles', handles, '--distortion', 'isometric']
            out.append(dict(name='deform/' + name, dim=3,
                            args=['--rest', rest, '--targets', init] + common,
                            check=['--rest', rest, '--targets', init, '--handles', handles]))
            if name == 'untwist':
                out.append(dict(name='untwist-twisted', dim=3,
                                args=['--rest', rest, '--init', init] + common,
                                check=['--rest', rest, '--targets', init, '--handles', handles]))
    if 'generated' in which:
        out += generated_cases(data, generator, work)
    return out


def diagonal_of_targets(check_args):
    """Bounding-box diagonal of the handle targets' file, for the checker's absolute tolerance."""
    path = None
    for flag in ('--targets', '--rest'):
        if flag in check_args:
            path = check_args[check_args.index(flag) + 1]
            break
    rows = []
    with open(path) as f:
        tokens = [line.split('#')[0].split() for line in f]
    tokens = [t for t in tokens if t]
    if path.endswith('.node'):
        n = int(tokens[0][0])
        rows = [[float(x) for x in t[1:4]] for t in tokens[1:1 + n]]
    else:  # plain-text problem: its initial block
        n = int(tokens[0][0])
        init = tokens[1 + n + 1:1 + n + 1 + n]
        rows = [[float(x) for x in t] for t in init]
    lo = [min(r[i] for r in rows) for i in range(len(rows[0]))]
    hi = [max(r[i] for r in rows) for i in range(len(rows[0]))]
    return sum((b - a) ** 2 for a, b in zip(lo, hi)) ** 0.5


VARIANTS = {
    'default': ([], 'the default run: --mode auto, full quality'),
    'full': (['--mode', 'full'], 'the full solve (--mode full); every run has --max-time at 90% of the timeout'),
    'until-valid': (['--until-valid'], 'untangling only (--until-valid): stops at the first verified map'),
}


def run_case(a, case, variant, work):
    out = os.path.join(work, '%s.%s%s' % (case['name'].replace('/', '_'), variant,
                                          '.node' if case['dim'] == 3 else '.obj'))
    report = out + '.json'
    # sa stops itself at 90% of the timeout and reports the map it reached; the timeout only
    # catches a run that overshoots by more than its last iteration.
    command = ([a.sa, 'map'] + case['args'] + VARIANTS[variant][0] +
               ['--out', out, '--report', report, '--no-png', '--force', '--quiet',
                '--max-time', repr(0.9 * a.timeout)] + a.extra)
    print('running %s (%s) ...' % (case['name'], variant), file=sys.stderr, flush=True)
    r = run_measured(command, a.timeout)
    row = dict(case=case['name'])
    if r is None:
        row['status'] = 'killed after %g s' % a.timeout
        return row
    row['wall'], row['peak'] = r['wall'], r['peak_kb'] / 1024.0 / 1024.0
    if not os.path.exists(report):
        row['status'] = 'sa exit %d: %s' % (r['code'], (r['err'].strip().splitlines() or [''])[-1])
        return row
    rep = json.load(open(report))
    row['elements'] = rep['input']['simplices']
    if 'infeasible' in rep:  # diagnosed before optimizing (geometry/quality/handle_feasibility.h)
        f = rep['infeasible']
        row['status'] = 'diagnosed infeasible (exit %d): %d of %d fixed simplices inverted, %d flat' % (
            r['code'], f['inverted'], f['fixed_simplices'], f['flat'])
        print('  ', row['status'], fmt(row['wall']), 's', file=sys.stderr, flush=True)
        return row
    row['before'] = rep['initial_quality']['inverted']
    row['mode'] = rep.get('mode', 'full')
    stages = {s['stage']: s for s in rep.get('stages', [])}
    if stages.get('fallback', {}).get('outcome') == 'replaced the result':
        row['mode'] += ', then the untangling fallback'
    stage = rep.get('vertex_stage', {}).get('iterations', 0)
    t = rep['times']
    if row['mode'] == 'submesh':
        m = rep['submesh']
        row['iterations'] = '%d in %d solves + %d' % (m['iterations'], m['solves'], stage)
        if stages.get('start untangling', {}).get('newton_steps'):
            row['iterations'] = ('untangle %d, ' % stages['start untangling']['newton_steps'] +
                                 row['iterations'])
        row['submesh'] = '%d rounds, %d solves, largest %d, %d rings' % (
            len(m['rounds']), m['solves'], m['largest_submesh'], m['max_rings'])
        row['stages'] = 'start %.2f, regions %.2f, vertex %.2f' % (
            m['times']['start'], m['times']['solves'], t['vertex_stage'])
    else:
        row['iterations'] = '%d + %d' % (len(rep['iterations']) - 1, stage)
        row['submesh'] = '-'
        row['stages'] = 'assembly %.2f, recovery %.2f, vertex %.2f' % (
            t['optimization'], t['recovery'], t['vertex_stage'])
    tol = 1e-6 * diagonal_of_targets(case['check'])
    c = subprocess.run([sys.executable, a.checker] + case['check'] + ['--result', out, '--tol', repr(tol)],
                       capture_output=True, text=True)
    try:
        chk = json.loads(c.stdout)
    except json.JSONDecodeError:
        chk = dict(ok=False, error=c.stdout + c.stderr)
    row['check'] = chk
    if chk.get('ok'):
        row['status'] = 'verified'
    elif not rep['verification']['success']:
        row['status'] = 'failed, as sa reports' + (
            ' (time limit %g s)' % (0.9 * a.timeout) if 'time limit' in rep.get('message', '') else '')
    else:
        row['status'] = 'NOT verified'
    if chk.get('ok') != rep['verification']['success']:
        row['status'] += ' (sa and the checker disagree!)'
    print('  ', row['status'], fmt(row['wall']), 's', file=sys.stderr, flush=True)
    return row


def table(rows):
    header = ('| case | elements | inverted before | inverted after | handle error | '
              'δ_con max / avg | δ_iso max / avg | mode | submeshes | iterations | stage times (s) | '
              'wall time (s) | peak memory (GB) | check_map.py |\n'
              '|---|---:|---:|---:|---:|---:|---:|:---:|---|---:|---|---:|---:|:---|\n')
    lines = []
    for r in rows:
        chk = r.get('check', {})
        con, iso = chk.get('conformal', [None, None]), chk.get('isometric', [None, None])
        lines.append('| %s | %s | %s | %s | %s | %s / %s | %s / %s | %s | %s | %s | %s | %s | %s | %s |' % (
            r['case'], fmt(r.get('elements')), fmt(r.get('before')), fmt(chk.get('inverted')),
            fmt(chk.get('handle_max_err')), fmt(con[0], 4), fmt(con[1], 4), fmt(iso[0], 4), fmt(iso[1], 4),
            r.get('mode', '-'), r.get('submesh', '-'), r.get('iterations', '-'), r.get('stages', '-'),
            fmt(r.get('wall'), 3), fmt(r.get('peak'), 2), r['status']))
    return header + '\n'.join(lines) + '\n'


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--sa', default=os.path.join(ROOT, 'build', 'bin', 'sa'))
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'))
    ap.add_argument('--checker', default=os.path.join(ROOT, '..', 'shared', 'tools', 'check_map.py'))
    ap.add_argument('--cases', default='tlc,deform,generated',
                    help='comma-separated: tlc, deform, generated')
    ap.add_argument('--generator', default=os.path.join(ROOT, 'build', 'bin', 'bench_generate_problem'))
    ap.add_argument('--only', help='run only the cases whose name contains this text')
    ap.add_argument('--variants', default='default,full,until-valid',
                    help='comma-separated: ' + ', '.join(VARIANTS))
    ap.add_argument('--timeout', type=float, default=600.0, help='seconds per run')
    ap.add_argument('--write', help='markdown file whose map-benchmarks section gets the tables')
    ap.add_argument('extra', nargs='*', help='arguments for every sa map run (after --)')
    a = ap.parse_args()

    work = tempfile.mkdtemp(prefix='sa-map-bench-')
    output = ''
    for variant in a.variants.split(','):
        rows = [run_case(a, case, variant, work)
                for case in cases(a.data, a.cases.split(','), a.generator, work)
                if not a.only or a.only in case['name']]
        output += '**%s**: %s\n\n%s\n' % (variant, VARIANTS[variant][1], table(rows))
    print(output)

    if a.write:
        write_section(a.write, 'map-benchmarks', 'python3 bench/map_benchmarks.py ' + ' '.join(sys.argv[1:]),
                      output)
    return 0


if __name__ == '__main__':
    sys.exit(main())
