#!/usr/bin/env python3
"""Runs `sa hex` with its default options (the hex count it aims at, labels computed) on every
mesh of ../shared/data/polycube/robustPolycube (B0, NY_2, pente, S3, M1_tet, cup) and of
../shared/data/tet, each with --report, --no-png and --max-time, into a temporary folder, and
checks each hex mesh with the independent checker bench/check_hex.py (against the input tets).
Prints a markdown table: the mesh and its tets; the exit status of `sa hex` (0 verified, 1 a stage
did not verify, 2 bad input) and the report's outcome; the hexes and the grid's cells per axis;
the report's scaled Jacobian min / mean; check_hex.py's verdict, its scaled Jacobian min and its
two-sided boundary distance (Hausdorff, as a fraction of the input's bounding-box diagonal); the
volume ratio hex / tet of the report and of check_hex.py; the report's time of the PolyCube, of
the PolyCube on the grid and of the whole run, with the wall time measured here; and the peak
memory (maximum resident set) of the run. A run that fails or is killed still gets a row.

  python3 bench/hex_benchmarks.py [--only NAME]... [--max-time 300] [--sa PATH] [--data DIR]
                                  [--keep DIR] [--write docs/performance.md]

--only keeps the meshes whose name (or folder/name) contains the text (repeatable); --keep writes
the outputs into DIR instead of a temporary folder; with --write, the table replaces the section
between <!-- hex-benchmarks:begin --> and <!-- hex-benchmarks:end --> of that file.
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile

from bench_common import fmt, run_measured, write_section

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CHECKER = os.path.join(HERE, 'check_hex.py')

# The folders of ../shared/data whose meshes are run, and the order of the known ones.
FOLDERS = ['polycube/robustPolycube', 'tet']
ORDER = ['B0', 'NY_2', 'pente', 'S3', 'M1_tet', 'cup']


def cases(data):
    """(name, folder/name, path) of the meshes to run, in table order."""
    found = []
    for folder in FOLDERS:
        paths = glob.glob(os.path.join(data, folder, '*.mesh'))
        names = sorted((os.path.basename(p)[:-len('.mesh')] for p in paths),
                       key=lambda n: (ORDER.index(n) if n in ORDER else len(ORDER), n))
        found += [(n, '%s/%s' % (os.path.basename(folder), n), os.path.join(data, folder, n + '.mesh'))
                  for n in names]
    return found


def count_tets(path):
    """The number of tets of a Medit mesh (read by check_hex's reader), or None."""
    sys.path.insert(0, HERE)
    try:
        import check_hex
        return len(check_hex.read_medit(path)['T'])
    except (OSError, ValueError):
        return None


def last_line(text, default):
    lines = [l for l in (text or '').strip().splitlines() if l.strip()]
    return lines[-1].strip() if lines else default


def run_case(a, name, tag, mesh, work):
    base = os.path.join(work, tag.replace('/', '_'))
    out, report = base + '.hex.mesh', base + '.json'
    for f in (out, report):
        if os.path.exists(f):
            os.remove(f)
    command = [a.sa, 'hex', '--mesh', mesh, '--out', out, '--report', report, '--no-png',
               '--max-time', str(a.max_time), '--quiet']
    print('running %s ...' % name, file=sys.stderr, flush=True)
    row = dict(name=name, tets=count_tets(mesh))
    timeout = 2 * a.max_time + 300
    r = run_measured(command, timeout)
    if r is None:
        row['code'] = 'killed'
        row['outcome'] = 'killed after %g s' % timeout
    else:
        row['code'], row['wall'] = r['code'], r['wall']
        row['peak'] = r['peak_kb'] / 1024.0 / 1024.0
        if os.path.exists(report):
            try:
                with open(report) as f:
                    row['report'] = json.load(f)
            except (OSError, ValueError) as e:
                row['outcome'] = 'unreadable report: %s' % e
        rep = row.get('report')
        if rep is not None:
            row['outcome'] = rep.get('outcome', '-')
        elif 'outcome' not in row:
            row['outcome'] = 'error: ' + last_line(r['err'], 'exit %d, no report' % r['code'])
    if os.path.exists(out):
        print('checking %s ...' % name, file=sys.stderr, flush=True)
        try:
            c = subprocess.run([sys.executable, CHECKER, '--hex', out, '--tets', mesh],
                               capture_output=True, text=True, timeout=3600)
            row['check'] = json.loads(c.stdout)
        except subprocess.TimeoutExpired:
            row['check'] = dict(ok=False, error='check_hex.py killed after 3600 s')
        except ValueError:
            row['check'] = dict(ok=False, error=last_line(c.stdout + c.stderr, 'no output'))
    return row


def get(d, *keys):
    """d[k0][k1]... or None when a level is missing."""
    for k in keys:
        if not isinstance(d, dict) or k not in d:
            return None
        d = d[k]
    return d


def table(rows):
    lines = ['| mesh | tets | sa exit | outcome | hexes | cells per axis | scaled Jacobian min / mean '
             '(report) | check_hex.py: ok / SJ min / Hausdorff | volume ratio (report / check_hex.py) | '
             'time (s): PolyCube, grid PolyCube, total (wall) | peak memory (GB) |',
             '|---|---|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        rep, chk = r.get('report') or {}, r.get('check')
        ver, times = get(rep, 'verification') or {}, get(rep, 'times') or {}
        cells = get(rep, 'quantization', 'cells_per_axis')
        cells = ' × '.join(str(c) for c in cells) if isinstance(cells, list) else '-'
        if chk is None:
            check = 'no output'
        elif 'error' in chk:
            check = 'error: ' + chk['error']
        else:
            check = '%s / %s / %s' % ('yes' if chk['ok'] else 'no', fmt(chk.get('scaled_jacobian_min'), 4),
                                      fmt(chk.get('hausdorff'), 3))
        volume = '%s / %s' % (fmt(ver.get('volume_ratio'), 5),
                              fmt(chk.get('volume_ratio'), 5) if chk else '-')
        time = '%s, %s, %s (%s)' % (fmt(times.get('polycube'), 3), fmt(times.get('grid_polycube'), 3),
                                    fmt(times.get('total'), 3), fmt(r.get('wall'), 3))
        lines.append('| %s | %s | %s | %s | %s | %s | %s / %s | %s | %s | %s | %s |' % (
            r['name'], fmt(r.get('tets')), r.get('code', '-'),
            str(r.get('outcome', '-')).replace('|', '\\|'), fmt(ver.get('hexes')), cells,
            fmt(get(ver, 'scaled_jacobian', 'min'), 4), fmt(get(ver, 'scaled_jacobian', 'mean'), 4),
            check.replace('|', '\\|'), volume, time, fmt(r.get('peak'), 2)))
    return '\n'.join(lines) + '\n'


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--sa', default=os.path.join(ROOT, 'build', 'bin', 'sa'), help='the sa binary')
    ap.add_argument('--data', default=os.path.join(ROOT, '..', 'shared', 'data'),
                    help='the data folder')
    ap.add_argument('--only', action='append', default=[],
                    help='run only the meshes whose name contains this text (repeatable)')
    ap.add_argument('--max-time', type=float, default=300.0, help='--max-time of each run')
    ap.add_argument('--keep', help='write the outputs into this folder instead of a temporary one')
    ap.add_argument('--write', help='markdown file whose hex-benchmarks section gets the table')
    a = ap.parse_args()
    selected = [(n, tag, path) for n, tag, path in cases(a.data)
                if not a.only or any(o in tag for o in a.only)]
    if not selected:
        print('no mesh selected in %s' % a.data, file=sys.stderr)
        return 2
    if a.keep:
        os.makedirs(a.keep, exist_ok=True)
        rows = [run_case(a, n, tag, path, a.keep) for n, tag, path in selected]
    else:
        with tempfile.TemporaryDirectory(prefix='sa-hex-bench-') as work:
            rows = [run_case(a, n, tag, path, work) for n, tag, path in selected]
    output = table(rows)
    print(output)
    if a.write:
        write_section(a.write, 'hex-benchmarks',
                      'python3 bench/hex_benchmarks.py ' + ' '.join(sys.argv[1:]), output)
    return 0


if __name__ == '__main__':
    sys.exit(main())
