"""Start-up and exit, side by side in one run (interleaved, RUNS rounds, medians):

- real rclpy (the reference venv, Fast DDS): `python talker.py`
- `labkit exec talker.py` with DDS on (live time, joins DDS on loopback, a private domain)
- `labkit exec talker.py` with LABKIT_DDS=off
- `labkit exec empty.py` (an empty script) with DDS on and off: the floor
- a fresh interpreter that activates labkit as `%load_ext labkit` does, then
  rclpy.init() + a node + a publisher (in-process, target < 1 s)

For the talker (publishes once at once, then 1 s at 10 Hz, then destroys its node and
shuts down), three figures per run, from the parent's wall clock (the child prints
time.time() at its points): start -> first publish returned, script end -> process gone
(exit: leaving DDS included), and the whole process (~1 s of it is the 10 Hz part). Target (issue 19): labkit exec start to first publish no
slower than real rclpy's, with DDS on and off.

    python benchmarks/bench_startup.py [--runs N] [--compare DIR]

--compare DIR adds the same `labkit exec` rows for another labkit tree (e.g. an older
commit: git archive <commit> labkit | tar -x -C DIR): before and after in one run.
    python -X importtime -m labkit exec empty.py     # what an empty script imports
"""
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).resolve().parent))
RUNS = 5

# a plain rclpy program: runs unchanged on real rclpy and under `labkit exec`
TALKER = '''
import time
import rclpy
from std_msgs.msg import String
rclpy.init(args=[])
node = rclpy.create_node('startup_talker')
publisher = node.create_publisher(String, 'chatter', 10)
msg = String()
msg.data = 'hello'
publisher.publish(msg)
print('FIRST', time.time(), flush=True)
ticks = []                         # then 1 s at 10 Hz: DDS is joined by the time it ends
node.create_timer(0.1, lambda: ticks.append(publisher.publish(msg)))
while len(ticks) < 10:
    rclpy.spin_once(node, timeout_sec=0.5)
node.destroy_node()
rclpy.shutdown()
print('END', time.time(), flush=True)
'''
EMPTY = "import time\nprint('END', time.time(), flush=True)\n"

# Timed inside the fresh interpreter, from before `import labkit` to the publisher.
IN_PROCESS = '''
import time
t0 = time.perf_counter()
import labkit
labkit.activate()
import rclpy
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node('startup_probe')
publisher = node.create_publisher(String, 'chatter', 10)
print(time.perf_counter() - t0)
node.destroy_node()
rclpy.shutdown()
'''


def _env(extra):
    # as a learner's terminal runs it: bytecode cached (PYTHONDONTWRITEBYTECODE would make
    # every run compile every module it imports)
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(('LABKIT_', 'ROS_', 'PYTHONPATH', 'PYTHONDONTWRITEBYTECODE'))}
    env.update(extra)
    return env


def timed(argv, env, cwd=REPO):
    """{'first': s, 'exit': s, 'total': s} of one process, from the parent's clock."""
    start = time.time()
    result = subprocess.run(argv, capture_output=True, text=True, timeout=120, env=env,
                            cwd=cwd)
    gone = time.time()
    if result.returncode != 0:
        raise RuntimeError(f'{argv} failed ({result.returncode}):\n{result.stderr[-2000:]}')
    marks = {}
    for line in result.stdout.splitlines():
        word, _, stamp = line.partition(' ')
        if word in ('FIRST', 'END'):
            marks[word] = float(stamp)
    out = {'total': gone - start, 'exit': gone - marks['END']}
    if 'FIRST' in marks:
        out['first'] = marks['FIRST'] - start
    return out


def import_ms(argv, env, cwd=REPO):
    """What `python -X importtime` reports for a run: the sum of its top-level imports (ms),
    and those among them over 5 ms."""
    result = subprocess.run([argv[0], '-X', 'importtime', *argv[1:]], capture_output=True,
                            text=True, timeout=120, env=env, cwd=cwd)
    total, big = 0, []
    for line in result.stderr.splitlines():
        if not line.startswith('import time:') or 'cumulative' in line:
            continue
        _, cumulative, name = line.split('|', 2)
        if name.startswith(' ') and not name.startswith('  '):     # a top-level import
            total += int(cumulative)
            if int(cumulative) > 5000:
                big.append(f'{name.strip()} {int(cumulative) / 1000:.0f}')
    return total / 1000, big


def in_process():
    result = subprocess.run([sys.executable, '-c', IN_PROCESS], capture_output=True,
                            text=True, timeout=120, cwd=REPO,
                            env=_env({'PYTHONPATH': str(REPO), 'LABKIT_TIME': 'live'}))
    if result.returncode != 0:
        raise RuntimeError(result.stderr[-2000:])
    return float(result.stdout.strip().splitlines()[-1])


def main():
    from _common import reference_python
    runs = RUNS
    if '--runs' in sys.argv:
        runs = int(sys.argv[sys.argv.index('--runs') + 1])
    tmp = Path(tempfile.mkdtemp(prefix='bench_startup_'))
    talker, empty = tmp / 'talker.py', tmp / 'empty.py'
    talker.write_text(TALKER, encoding='utf-8')
    empty.write_text(EMPTY, encoding='utf-8')
    domain = str(random.randint(150, 199))
    dds = {'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST', 'ROS_DOMAIN_ID': domain}
    labkit = [sys.executable, '-m', 'labkit', 'exec']
    on = _env({'PYTHONPATH': str(REPO), 'LABKIT_TIME': 'live', 'LABKIT_DDS': 'on', **dds})
    off = _env({'PYTHONPATH': str(REPO), 'LABKIT_TIME': 'live', 'LABKIT_DDS': 'off'})
    rows = {}
    real = reference_python()
    if real is not None:
        rows['real rclpy (Jazzy, Fast DDS)'] = ([real, str(talker)], _env(dds))
    else:
        print('real rclpy: reference venv not found (set ROSREF_PYTHON)')
    rows['labkit exec, DDS on'] = (labkit + [str(talker)], on)
    rows['labkit exec, DDS off'] = (labkit + [str(talker)], off)
    rows['labkit exec empty.py, DDS on'] = (labkit + [str(empty)], on)
    rows['labkit exec empty.py, DDS off'] = (labkit + [str(empty)], off)
    if '--compare' in sys.argv:
        other = str(Path(sys.argv[sys.argv.index('--compare') + 1]).resolve())
        for label, (argv, env) in list(rows.items()):
            if label.startswith('labkit'):
                rows[label + ' [compare]'] = (argv, dict(env, PYTHONPATH=other), other)
    figures = {label: [] for label in rows}
    inside = []
    for label, (argv, env, *cwd) in rows.items():   # a warm-up round, not counted
        timed(argv, env, *cwd)
    for _ in range(runs):                         # interleaved: load hits every row alike
        for label, (argv, env, *cwd) in rows.items():
            figures[label].append(timed(argv, env, *cwd))
        inside.append(in_process())
    try:
        load = os.getloadavg()[0]
        print(f'{runs} rounds after a warm-up, interleaved; load average {load:.1f} at the end')
    except OSError:
        print(f'{runs} rounds after a warm-up, interleaved')
    print(f"{'':41} {'start->first publish':>21} {'exit':>12} {'whole process':>14}  (medians; range)")

    def cell(values):
        if not values:
            return f"{'-':>12}"
        return f'{statistics.median(values):>6.3f} s'

    for label, runs_ in figures.items():
        first = [r['first'] for r in runs_ if 'first' in r]
        exit_ = [r['exit'] for r in runs_]
        total = [r['total'] for r in runs_]
        span = f"{min(total):.2f}-{max(total):.2f}"
        print(f'{label:41} {cell(first):>21} {cell(exit_):>12} {cell(total):>14}  ({span})')
    ref = figures.get('real rclpy (Jazzy, Fast DDS)')
    if ref:
        base = statistics.median(r['first'] for r in ref)
        for label in [k for k in figures if k.startswith('labkit exec, DDS')]:
            mine = statistics.median(r['first'] for r in figures[label])
            print(f'{label}: start->first publish {mine / base:.2f}x real rclpy '
                  f'(target <= 1x)')
    for label, (argv, env, *cwd) in rows.items():
        if 'empty.py' in label or label.startswith('labkit exec, DDS'):
            ms, big = import_ms(argv, env, *cwd)
            print(f'imports, {label}: {ms:.0f} ms ({", ".join(big) or "none over 5 ms"})')
    print(f'in process, import labkit -> activate -> init -> node -> publisher: median '
          f'{statistics.median(inside):.3f} s (target < 1 s)')


if __name__ == '__main__':
    main()
