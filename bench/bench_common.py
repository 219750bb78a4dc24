"""Helpers shared by the benchmark harnesses: measured child runs, number formatting, and
replacing a marked section of BENCHMARKS.md."""
import datetime
import json
import os
import platform
import signal
import subprocess
import sys


def run_measured(command, timeout):
    """Runs `command` in a child Python that reports the child's wall time and peak RSS.
    Returns dict(code, wall, peak_kb, out, err), or None when it was killed after `timeout` s."""
    wrapper = ('import json,resource,subprocess,sys,time\n'
               't=time.time()\n'
               'p=subprocess.run(sys.argv[1:],stdout=subprocess.PIPE,stderr=subprocess.PIPE,text=True)\n'
               'w=time.time()-t\n'
               'm=resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss\n'
               'print(json.dumps(dict(code=p.returncode,wall=w,peak_kb=m,out=p.stdout,err=p.stderr[-4000:])))\n')
    # A session of its own, so that a timeout kills `sa` too, not only the wrapper.
    p = subprocess.Popen([sys.executable, '-c', wrapper] + command, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        out, _ = p.communicate(timeout=timeout)
        return json.loads(out)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        return None


def check_uv(checker, mesh, out):
    """The JSON of `check_map.py --rest mesh --result out --uv`, or dict(ok=False, error=...)."""
    c = subprocess.run([sys.executable, checker, '--rest', mesh, '--result', out, '--uv'],
                       capture_output=True, text=True)
    try:
        return json.loads(c.stdout)
    except json.JSONDecodeError:
        return dict(ok=False, error=(c.stdout + c.stderr).strip())


def fmt(x, digits=3):
    if x is None:
        return '-'
    if isinstance(x, float):
        if x != x or x in (float('inf'), float('-inf')):
            return 'inf'
        return ('%.' + str(digits) + 'g') % x
    return str(x)


def write_section(path, marker, command, output):
    """Replaces the text between <!-- marker:begin --> and <!-- marker:end --> of `path` (or
    appends it) with `output`, headed by the date, the machine and `command`."""
    begin, end = '<!-- %s:begin -->' % marker, '<!-- %s:end -->' % marker
    section = ('%s\nMeasured %s on %s (%d cores), with\n\n```\n%s\n```\n\n%s%s' %
               (begin, datetime.date.today().isoformat(), platform.node(), os.cpu_count(), command,
                output, end))
    text = open(path).read() if os.path.exists(path) else ''
    if begin in text and end in text:
        text = text[:text.index(begin)] + section + text[text.index(end) + len(end):]
    else:
        text += '\n' + section + '\n'
    tmp = path + '.tmp'
    with open(tmp, 'w') as f:
        f.write(text)
    os.replace(tmp, path)
