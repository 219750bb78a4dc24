#!/usr/bin/env python3
"""What a cold build costs, unit by unit: clones a commit of this repository into a temporary
folder, builds the given targets there with scripts/build.sh (or scripts/build-sanitized.sh, with
--sanitized), every compile step run under /usr/bin/time, and prints a markdown table: wall time
of the build (configuration included), compile CPU time in all, the heaviest units (CPU seconds
and peak memory) and the CPU per target.

  python3 bench/build_time.py [--ref HEAD] [--sanitized] [--targets sa] [--jobs N] [--top 25]
                              [--time-trace 1] [--cmake-args "-DSA_NATIVE=ON"] [--write FILE]

--time-trace K recompiles the K heaviest units with clang++-14 -ftime-trace (same flags) and
lists where their front end spends its time: the headers parsed and the templates instantiated,
summed by name. --write FILE puts the table between <!-- build-time:begin --> and
<!-- build-time:end --> of FILE (<!-- build-time-sanitized:... --> with --sanitized).

Nothing is installed and no cache is used: the clone is built from scratch, as CI does. Run it on
an otherwise idle machine: the wall time counts what the cores were doing.
"""
import argparse
import collections
import json
import os
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

from bench_common import write_section

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# Runs the compiler under /usr/bin/time: one line per unit, "wall user sys max-rss-kb output".
LAUNCHER = '''#!/bin/sh
out=""
prev=""
for a in "$@"; do
    [ "$prev" = "-o" ] && out=$a
    prev=$a
done
exec /usr/bin/time -a -o "$SA_COMPILE_LOG" -f "%e %U %S %M $out" "$@"
'''


def target_of(output):
    """The CMake target of an object file: CMakeFiles/<target>.dir/..."""
    parts = output.split('/')
    for p in parts:
        if p.endswith('.dir'):
            return p[:-4]
    return '?'


def unit_name(output):
    """The source of an object file, relative to the tree: .../<target>.dir/<source>.o"""
    i = output.find('.dir/')
    name = output[i + 5:] if i >= 0 else output
    for suffix in ('.o', '.gch', '.pch'):
        if name.endswith(suffix):
            name = name[:-len(suffix)]
    return name


def read_log(path):
    units = []
    for line in open(path):
        fields = line.split(None, 4)
        if len(fields) < 5 or not fields[0][0].isdigit():
            continue  # a line of the compiler's own, should /usr/bin/time report a failure
        wall, user, system, rss = float(fields[0]), float(fields[1]), float(fields[2]), int(fields[3])
        out = fields[4].strip()
        units.append(dict(output=out, target=target_of(out), unit=unit_name(out),
                          cpu=user + system, wall=wall, rss_mb=rss / 1024.0))
    return units


def time_trace(build, output, top):
    """Recompiles the unit that produced `output` with clang++-14 -ftime-trace; returns the
    front end's time (s) and the headers and instantiations that took the most."""
    commands = json.load(open(os.path.join(build, 'compile_commands.json')))
    entry = next((c for c in commands if ' -o ' + output + ' ' in c['command']), None)
    if entry is None:
        return None
    args = shlex.split(entry['command'])
    # Drop the launcher (ours, then /usr/bin/time's arguments are not in the database) and the
    # compiler; keep the flags, with GCC-only warnings dropped.
    while args and not args[0].endswith(('g++', 'c++', 'clang++-14', 'clang++')):
        args.pop(0)
    flags = [a for a in args[1:] if a not in ('-Wno-maybe-uninitialized',)]
    with tempfile.TemporaryDirectory() as tmp:
        obj = os.path.join(tmp, 'unit.o')
        i = flags.index('-o')
        flags[i + 1] = obj
        subprocess.run(['clang++-14', '-ftime-trace', '-ftime-trace-granularity=1000'] + flags,
                       cwd=entry['directory'], check=True, capture_output=True)
        trace = json.load(open(os.path.join(tmp, 'unit.json')))
    totals = collections.Counter()
    frontend = 0.0
    for event in trace['traceEvents']:
        name, dur = event.get('name'), event.get('dur', 0) / 1e6
        if name == 'Total Frontend':
            frontend = dur
        elif name in ('Source', 'InstantiateFunction', 'InstantiateClass', 'ParseClass',
                      'OptFunction', 'CodeGen Function') and 'args' in event:
            detail = event['args'].get('detail', '')
            if name == 'Source':
                detail = detail.replace('/usr/include/', '')
            totals[(name, detail[:90])] += dur
    totals_by_kind = collections.Counter()
    for event in trace['traceEvents']:
        if event.get('name', '').startswith('Total '):
            totals_by_kind[event['name'][6:]] = event.get('dur', 0) / 1e6
    return dict(frontend=frontend, kinds=totals_by_kind, top=totals.most_common(top))


def table(units, wall, what, top):
    """The markdown summary line, the heaviest units and the CPU per target."""
    total = sum(u['cpu'] for u in units)
    heaviest = sorted(units, key=lambda u: -u['cpu'])
    lines = ['%s: **%.0f s wall**, %.0f s of compile CPU in %d units (largest %.1f s; peak '
             'memory of a unit %.2f GB).\n' %
             (what, wall, total, len(units), heaviest[0]['cpu'] if units else 0,
              max((u['rss_mb'] for u in units), default=0) / 1024)]
    lines.append('| unit (target) | CPU s | peak MB |')
    lines.append('|---|---:|---:|')
    for u in heaviest[:top]:
        lines.append('| `%s` (%s) | %.1f | %.0f |' % (u['unit'], u['target'], u['cpu'],
                                                    u['rss_mb']))
    by_target = collections.defaultdict(lambda: [0, 0.0])
    for u in units:
        by_target[u['target']][0] += 1
        by_target[u['target']][1] += u['cpu']
    lines.append('')
    lines.append('| target | units | CPU s | share |')
    lines.append('|---|---:|---:|---:|')
    for name, (count, cpu) in sorted(by_target.items(), key=lambda kv: -kv[1][1]):
        lines.append('| %s | %d | %.0f | %.0f%% |' % (name, count, cpu,
                                                      100.0 * cpu / max(total, 1e-9)))
    return lines


def trace_lines(unit, trace):
    lines = ['', '`clang++-14 -ftime-trace` of `%s`: front end %.1f s (%s).' % (
        unit, trace['frontend'],
        ', '.join('%s %.1f s' % (k, v) for k, v in trace['kinds'].most_common(6))), '',
        '| what | name | s |', '|---|---|---:|']
    for (kind, detail), seconds in trace['top']:
        lines.append('| %s | `%s` | %.2f |' % (kind, detail.replace('|', '\\|'), seconds))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--ref', default='HEAD', help='the commit to build (default HEAD)')
    parser.add_argument('--sanitized', action='store_true',
                        help="the clang build with sanitizers of scripts/build-sanitized.sh")
    parser.add_argument('--targets', nargs='*', default=[], help='build targets (default all)')
    parser.add_argument('--jobs', type=int, default=os.cpu_count())
    parser.add_argument('--top', type=int, default=25, help='units listed')
    parser.add_argument('--time-trace', type=int, default=0, metavar='K',
                        help='profile the K heaviest units with clang -ftime-trace')
    parser.add_argument('--cmake-args', default='',
                        help='more arguments for cmake (--cmake-args=-DX=Y for one that starts '
                             'with a dash)')
    parser.add_argument('--keep', help='build in this folder (new or empty) and keep it')
    parser.add_argument('--log', help='also copy the per-unit log to this file')
    parser.add_argument('--write', help='put the table into this file (docs/performance.md)')
    args = parser.parse_args()

    if args.keep and os.path.exists(args.keep) and os.listdir(args.keep):
        sys.exit('build_time.py: --keep %s: not an empty folder' % args.keep)
    work = args.keep or tempfile.mkdtemp(prefix='sa-build-time-')
    try:
        source = os.path.join(work, 'source')
        build = os.path.join(source, 'build-asan' if args.sanitized else 'build')
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        subprocess.run(['git', 'clone', '-q', '--no-checkout', ROOT, source], check=True)
        subprocess.run(['git', '-C', source, 'checkout', '-q',
                        subprocess.check_output(['git', '-C', ROOT, 'rev-parse', args.ref],
                                                text=True).strip()], check=True)
        launcher = os.path.join(work, 'timed-compile.sh')
        with open(launcher, 'w') as f:
            f.write(LAUNCHER)
        os.chmod(launcher, 0o755)
        log = os.path.join(work, 'units.log')
        env = dict(os.environ, SA_COMPILE_LOG=log)
        # The project's own build scripts, as a user and CI run them, with the compiler timed.
        script = 'build-sanitized.sh' if args.sanitized else 'build.sh'
        if 'SA_CMAKE_ARGS' not in open(os.path.join(source, 'scripts', script)).read():
            sys.exit('build_time.py: %s of %s takes no SA_CMAKE_ARGS; measure a later commit' %
                     (script, args.ref))
        env['SA_CMAKE_ARGS'] = ' '.join(['-DCMAKE_CXX_COMPILER_LAUNCHER=' + launcher] +
                                        shlex.split(args.cmake_args))
        env['SA_BUILD_JOBS'] = str(args.jobs)
        start = time.time()
        subprocess.run(['bash', os.path.join('scripts', script)] + args.targets, cwd=source,
                       check=True, stdout=subprocess.DEVNULL, env=env)
        wall = time.time() - start
        if args.log:
            shutil.copy(log, args.log)

        units = read_log(log)
        commit = subprocess.check_output(['git', '-C', source, 'log', '-1', '--format=%h %s'],
                                         text=True).strip()
        what = '%s build of `%s` (%s), %s, %d jobs' % (
            'Sanitized clang' if args.sanitized else 'Release', ' '.join(args.targets) or 'all',
            commit, args.cmake_args or 'default options', args.jobs)
        lines = table(units, wall, what, args.top)
        print('\n'.join(lines), flush=True)
        for u in sorted(units, key=lambda u: -u['cpu'])[:args.time_trace]:
            trace = time_trace(build, u['output'], 12)
            if trace is not None:
                more = trace_lines(u['unit'], trace)
                print('\n'.join(more), flush=True)
                lines += more
        if args.write:
            marker = 'build-time-sanitized' if args.sanitized else 'build-time'
            write_section(args.write, marker, 'python3 bench/build_time.py ' +
                          ' '.join(shlex.quote(a) for a in sys.argv[1:]), '\n'.join(lines) + '\n')
    finally:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == '__main__':
    main()
