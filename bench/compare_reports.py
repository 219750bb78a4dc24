"""Compares the JSON reports of two runs of bench/engine_comparison.sh: every number and string
of each report (apart from times, paths and messages), numbers to 1e-9 relative.

usage: python3 bench/compare_reports.py OLD_DIR NEW_DIR
"""
import json
import math
import os
import sys

SKIP = ('time', 'seconds', 'source', 'mesh', 'out', 'vtu', 'png', 'report', 'path', 'message',
        'description', 'note', 'termination', 'stopped', 'peak')


def flat(d, p=''):
    out = {}
    if isinstance(d, dict):
        for k, v in d.items():
            out.update(flat(v, p + '/' + k))
    elif isinstance(d, list):
        for i, v in enumerate(d):
            out.update(flat(v, p + '[%d]' % i))
    else:
        out[p] = d
    return out


def main(old, new):
    for f in sorted(os.listdir(old)):
        if not f.endswith('.json'):
            continue
        if not os.path.exists(os.path.join(new, f)):
            print(f, 'missing in', new)
            continue
        a = flat(json.load(open(os.path.join(old, f))))
        b = flat(json.load(open(os.path.join(new, f))))
        diffs = []
        for k in sorted(set(a) | set(b)):
            if any(s in k.lower() for s in SKIP):
                continue
            x, y = a.get(k), b.get(k)
            if isinstance(x, float) and isinstance(y, float) and math.isfinite(x):
                if abs(x - y) <= 1e-9 * max(1.0, abs(x), abs(y)):
                    continue
            elif x == y:
                continue
            diffs.append((k, x, y))
        print(f, 'same' if not diffs else '%d differences, first:' % len(diffs))
        for d in diffs[:5]:
            print('   ', d)


if __name__ == '__main__':
    main(sys.argv[1], sys.argv[2])
