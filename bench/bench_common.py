"""Helpers shared by the benchmark harnesses: measured child runs, number formatting, and
replacing a marked section of a document (docs/performance.md)."""
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


def machine():
    """The host, its processor and its cores, in words."""
    model = platform.processor() or platform.machine()
    try:
        with open('/proc/cpuinfo') as f:
            model = next(line.split(':', 1)[1].strip() for line in f if line.startswith('model name'))
    except (OSError, StopIteration):
        pass
    return '%s (%s, %d cores)' % (platform.node(), model, os.cpu_count())


def commit():
    """The commit of the checkout the benchmark runs in ('+ changes' when its code has uncommitted
    changes)."""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    try:
        head = subprocess.run(['git', '-C', root, 'rev-parse', '--short', 'HEAD'], capture_output=True,
                              text=True, check=True).stdout.strip()
        # Documents do not count: the tables are written into them.
        dirty = subprocess.run(['git', '-C', root, 'status', '--porcelain', '--untracked-files=no',
                                '--', '.', ':!*.md'], capture_output=True, text=True,
                               check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return 'unknown'
    return head + (' + changes' if dirty else '')


def write_section(path, marker, command, output):
    """Replaces the text between <!-- marker:begin --> and <!-- marker:end --> of `path` (or
    appends it) with `output`, headed by the date, the machine and `command`. The commit measured
    goes to stderr, not into the document (documents describe the project as it is)."""
    begin, end = '<!-- %s:begin -->' % marker, '<!-- %s:end -->' % marker
    print('%s: measured at commit %s' % (marker, commit()), file=sys.stderr)
    section = ('%s\nMeasured %s on %s, with\n\n```\n%s\n```\n\n%s%s' %
               (begin, datetime.date.today().isoformat(), machine(), command, output, end))
    text = open(path).read() if os.path.exists(path) else ''
    if begin in text and end in text:
        text = text[:text.index(begin)] + section + text[text.index(end) + len(end):]
    else:
        text += '\n' + section + '\n'
    tmp = path + '.tmp'
    with open(tmp, 'w') as f:
        f.write(text)
    os.replace(tmp, path)
