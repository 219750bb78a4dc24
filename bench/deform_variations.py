#!/usr/bin/env python3
"""Generated deformations of the Figure 16 class at 20k to 90k tetrahedra: bars of several lengths
and resolutions (bench_bar_pose), bent by 45 to 180 degrees, twisted by a quarter and a half
turn, twisted and bent, and translated, posed by `sa deform` from the rest shape and the targets
of the two end slabs alone. Prints deform_benchmarks.py's table and a last line counting the
cases verified by ../shared/tools/check_map.py (no inverted or degenerate tetrahedron, no
interior edge wrapped twice, handles at their targets); exits 1 when one is not.

  python3 bench/deform_variations.py [--bin build/bin] [--only TEXT] [--timeout S]
                                     [--write docs/performance.md]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from bench_common import run_measured, write_section
from deform_benchmarks import HEADER, check, row

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# (length, boxes across): boxes along the bar make cubes, 6 tetrahedra each.
BARS = [(5, 8), (5, 10), (5, 12), (8, 8), (3, 12)]
POSES = ([('bend', ['--bend-degrees', str(a)]) for a in (45, 90, 135, 180)] +
         [('twist', ['--twist-degrees', str(a)]) for a in (90, 180)] +
         [('bend-twist', ['--bend-degrees', '90', '--twist-degrees', '180']),
          ('translate', ['--shift', '1'])])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--bin', default=os.path.join(ROOT, 'build', 'bin'))
    ap.add_argument('--checker', default=os.path.join(ROOT, '..', 'shared', 'tools', 'check_map.py'))
    ap.add_argument('--only', help='run only the cases whose name contains this text')
    ap.add_argument('--timeout', type=float, default=300.0, help='seconds per run')
    ap.add_argument('--write', help='markdown file whose deform-variations section gets the table')
    a = ap.parse_args()

    work = tempfile.mkdtemp(prefix='sa-deform-variations-')
    lines, verified, total = [], 0, 0
    for length, across in BARS:
        for pose, angles in POSES:
            name = 'bar %d:1:1 x%d %s %s' % (length, across, pose, ' '.join(angles[1::2]))
            if a.only and a.only not in name:
                continue
            prefix = os.path.join(work, 'case%d' % total)
            subprocess.run([os.path.join(a.bin, 'bench_bar_pose'), '--pose', pose, '--prefix',
                            prefix, '--length', str(length), '--cross-cells', str(across),
                            '--length-cells', str(length * across)] + angles,
                           check=True, capture_output=True)
            total += 1
            print('%s ...' % name, file=sys.stderr, flush=True)
            out, report_path = prefix + '-posed.vtk', prefix + '.json'
            r = run_measured([os.path.join(a.bin, 'sa'), 'deform', '--rest', prefix + '.mesh',
                              '--targets', prefix + '_targets.txt', '--out', out, '--report',
                              report_path, '--no-png', '--force', '--quiet'], a.timeout)
            report = None
            if r is not None and os.path.exists(report_path) and r['code'] in (0, 1):
                with open(report_path) as f:
                    report = json.load(f)
            checked = check(a.checker, prefix + '.mesh', out,
                            ['--handles', prefix + '_handles.txt', '--targets',
                             prefix + '_posed_handles.mesh']) if report else {}
            verified += bool(checked.get('ok'))
            lines.append(row(name, r, report, checked))
    output = ('`sa deform` on generated bars (default options):\n\n' + HEADER + '\n'.join(lines) +
              '\n\n%d of %d verified by check_map.py.\n' % (verified, total))
    print(output)
    if a.write:
        write_section(a.write, 'deform-variations',
                      'python3 bench/deform_variations.py ' + ' '.join(sys.argv[1:]), output)
    return 0 if verified == total else 1


if __name__ == '__main__':
    sys.exit(main())
