#!/usr/bin/env python3
"""Compares builds (or environments) of one command run by run, interleaved, on a shared machine.

Each variant is NAME=EXECUTABLE, optionally followed by ,VAR=VALUE environment settings. The
variants run one after the other, RUNS times over, so that a change in the machine's load hits them
alike. For each run the process's CPU time (user + system, from wait4: what the process itself
spent, less sensitive to other jobs than the wall time), its wall time and its minor page faults
are recorded; the medians and quartiles are printed per variant.

  python3 bench/interleaved_runs.py --runs 60 \\
      --variant static=build/bin/sa --variant shared=build-shared/bin/sa \\
      --variant limit1=build/bin/sa,OMP_THREAD_LIMIT=1 \\
      -- map --rest ../shared/data/tlc/param2d/input --out /tmp/p.obj --until-valid --no-png --force --quiet
"""
import argparse
import os
import statistics
import subprocess
import sys
import time


def quartile(values, fraction):
    ordered = sorted(values)
    return ordered[int(fraction * (len(ordered) - 1))]


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--runs', type=int, default=30)
    parser.add_argument('--variant', action='append', required=True,
                        help='NAME=EXECUTABLE[,VAR=VALUE...]')
    parser.add_argument('arguments', nargs=argparse.REMAINDER,
                        help='the command line after the executable (after --)')
    args = parser.parse_args()
    command = args.arguments[1:] if args.arguments[:1] == ['--'] else args.arguments
    variants = []
    for spec in args.variant:
        name, rest = spec.split('=', 1)
        parts = rest.split(',')
        env = dict(os.environ)
        env.update(part.split('=', 1) for part in parts[1:])
        variants.append((name, parts[0], env))

    samples = {name: [] for name, _, _ in variants}
    with open(os.devnull, 'w') as devnull:
        for _ in range(args.runs):
            for name, executable, env in variants:
                start = time.perf_counter()
                process = subprocess.Popen([executable] + command, env=env, stdout=devnull,
                                           stderr=devnull)
                _, status, usage = os.wait4(process.pid, 0)
                wall = time.perf_counter() - start
                if status != 0:
                    sys.exit(f'{name}: exit status {status >> 8}')
                samples[name].append((usage.ru_utime + usage.ru_stime, wall, usage.ru_minflt))

    print(f'{args.runs} interleaved runs of: {" ".join(command)}')
    print('| variant | CPU median (s) | CPU quartiles | wall median (s) | wall quartiles | '
          'minor faults |')
    print('|---|---:|---:|---:|---:|---:|')
    for name, _, _ in variants:
        cpu = [s[0] for s in samples[name]]
        wall = [s[1] for s in samples[name]]
        faults = [s[2] for s in samples[name]]
        print(f'| {name} | {statistics.median(cpu):.4f} | {quartile(cpu, .25):.4f}-'
              f'{quartile(cpu, .75):.4f} | {statistics.median(wall):.4f} | '
              f'{quartile(wall, .25):.4f}-{quartile(wall, .75):.4f} | '
              f'{statistics.median(faults):.0f} |')
    with open('/proc/loadavg') as load:
        print(f'load average at the end: {" ".join(load.read().split()[:3])}')


if __name__ == '__main__':
    main()
