"""labkit over DDS against real rclpy (Jazzy, Fast DDS), same machine, loopback only.

Prints, in one run:
  - small std_msgs/String throughput: labkit -> real, real -> labkit, real -> real
    (target: labkit's rows at least real -> real's);
  - ping-pong round trip median: labkit <-> real echo, real <-> real (target <= 1.5x);
  - a 640x480 bgr8 Image stream at 30 Hz, labkit -> labkit, labkit -> real, real -> real,
    real -> labkit in interleaved rounds: median and mean frame delay, frames lost
    (target: labkit's rows no slower than real -> real in median and mean, none lost);
  - process start to first message across processes (labkit exec talker -> listener,
    and real -> real; target < 2 s).

Every program below is plain rclpy, run with `python -m labkit exec` (which joins DDS)
or with the reference interpreter ($ROSREF_PYTHON, else .venv-rosref/bin/python).

    python benchmarks/bench_dds.py [--rounds N (3)] [--only image]
"""
import json
import os
import random
import statistics
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SECONDS = 3.0


# ----------------------------------------------------------------- the programs
def _spin(node, seconds):
    import rclpy
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.01)


def _wait_matched(node, pub, timeout=10.0):
    import rclpy
    end = time.monotonic() + timeout
    while pub.get_subscription_count() == 0 and time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.05)
    _spin(node, 0.5)            # the DDS reader matches a moment after discovery


def sink():
    """Count std_msgs/String on 'bench' until SECONDS after the first one."""
    import rclpy
    from std_msgs.msg import String
    rclpy.init(args=[])
    node = rclpy.create_node('bench_sink')
    stamps = []
    node.create_subscription(String, 'bench', lambda m: stamps.append(time.monotonic()), 10)
    print('ready', flush=True)
    end = time.monotonic() + 30
    while time.monotonic() < end and (not stamps or time.monotonic() < stamps[0] + SECONDS):
        rclpy.spin_once(node, timeout_sec=0.01)
    span = (stamps[-1] - stamps[0]) if len(stamps) > 1 else 0
    print(json.dumps({'received': len(stamps), 'per_s': (len(stamps) - 1) / span if span else 0,
                      'socket_drops': socket_drops()}))


def source():
    """Publish std_msgs/String on 'bench' as fast as possible for SECONDS + 1."""
    import rclpy
    from std_msgs.msg import String
    rclpy.init(args=[])
    node = rclpy.create_node('bench_source')
    pub = node.create_publisher(String, 'bench', 10)
    _wait_matched(node, pub)
    msg, sent = String(data='Hello World'), 0
    rate = float(os.environ.get('BENCH_RATE', 0))   # 0: as fast as it goes
    start = time.monotonic()
    end = start + SECONDS + 1
    while time.monotonic() < end:
        pub.publish(msg)
        sent += 1
        rclpy.spin_once(node, timeout_sec=0)
        while rate and time.monotonic() < start + sent / rate:
            pass
    print(json.dumps({'sent': sent}))


def echo():
    import rclpy
    from std_msgs.msg import String
    rclpy.init(args=[])
    node = rclpy.create_node('bench_echo')
    pub = node.create_publisher(String, 'pong', 10)
    last = [None]

    def answer(msg):
        pub.publish(msg)
        last[0] = time.monotonic()
    node.create_subscription(String, 'ping', answer, 10)
    print('ready', flush=True)
    end = time.monotonic() + 30       # until the pinger has been quiet for 2 s
    while time.monotonic() < end and (last[0] is None or time.monotonic() < last[0] + 2):
        rclpy.spin_once(node, timeout_sec=0.01)
    print(json.dumps({}))


def pinger():
    import rclpy
    from std_msgs.msg import String
    rclpy.init(args=[])
    node = rclpy.create_node('bench_pinger')
    got = []
    node.create_subscription(String, 'pong', got.append, 10)
    pub = node.create_publisher(String, 'ping', 10)
    _wait_matched(node, pub)
    rtts = []
    for i in range(300):
        got.clear()
        t0 = time.perf_counter()
        pub.publish(String(data=str(i)))
        end = time.monotonic() + 1.0
        while not got and time.monotonic() < end:
            rclpy.spin_once(node, timeout_sec=0.001)
        if got:
            rtts.append(time.perf_counter() - t0)
    print(json.dumps({'median_ms': statistics.median(rtts) * 1e3 if rtts else None,
                      'answered': len(rtts)}))


def image_sink():
    import rclpy
    from sensor_msgs.msg import Image
    rclpy.init(args=[])
    node = rclpy.create_node('bench_image_sink')
    got, delays = [], []

    def frame(m):
        got.append(m.header.frame_id)
        delays.append(time.time() - m.header.stamp.sec - m.header.stamp.nanosec * 1e-9)
    node.create_subscription(Image, 'image', frame, 10)
    print('ready', flush=True)
    end = time.monotonic() + 25
    while time.monotonic() < end and len(set(got)) < 90:
        rclpy.spin_once(node, timeout_sec=0.01)
        if got and got[-1] == '89':
            _spin(node, 0.5)
            break
    print(json.dumps({'received': len(set(got)), 'socket_drops': socket_drops(),
                      'delay_ms': statistics.median(delays) * 1e3 if delays else None,
                      'mean_ms': statistics.fmean(delays) * 1e3 if delays else None,
                      'max_ms': max(delays) * 1e3 if delays else None}))


def socket_drops():
    """Datagrams the kernel dropped on this process's UDP sockets (a full receive
    buffer), from /proc/net/udp; None where there is no such file."""
    try:
        inodes = {os.readlink(f'/proc/self/fd/{fd}')[8:-1] for fd in os.listdir('/proc/self/fd')
                  if os.path.islink(f'/proc/self/fd/{fd}')}
        rows = [line.split() for name in ('udp', 'udp6')
                for line in Path(f'/proc/net/{name}').read_text().splitlines()[1:]]
    except OSError:
        return None
    return sum(int(row[-1]) for row in rows if row[9] in inodes)


def image_source():
    import rclpy
    from sensor_msgs.msg import Image
    rclpy.init(args=[])
    node = rclpy.create_node('bench_image_source')
    pub = node.create_publisher(Image, 'image', 10)
    _wait_matched(node, pub)
    img = Image(height=480, width=640, encoding='bgr8', step=1920)
    img.data = bytes(640 * 480 * 3)
    start = time.monotonic()
    for i in range(90):                  # 3 s at 30 Hz
        img.header.frame_id = str(i)
        now = time.time()                # the sink's clock is this one: same machine
        img.header.stamp.sec, img.header.stamp.nanosec = int(now), int(now % 1 * 1e9)
        pub.publish(img)
        while time.monotonic() < start + (i + 1) / 30:
            rclpy.spin_once(node, timeout_sec=0.005)
    _spin(node, 1.0)
    print(json.dumps({'sent': 90}))


def first_listener():
    import rclpy
    from std_msgs.msg import String
    rclpy.init(args=[])
    node = rclpy.create_node('bench_first_listener')
    got = []
    node.create_subscription(String, 'first', lambda m: got.append(time.time()), 10)
    print('ready', flush=True)
    end = time.monotonic() + 20
    while not got and time.monotonic() < end:
        rclpy.spin_once(node, timeout_sec=0.01)
    print(json.dumps({'first_at': got[0] if got else None}))


def first_talker():
    import rclpy
    from std_msgs.msg import String
    rclpy.init(args=[])
    node = rclpy.create_node('bench_first_talker')
    pub = node.create_publisher(String, 'first', 10)
    end = time.monotonic() + 15
    while time.monotonic() < end:     # like a talker: publish on a timer from the start
        pub.publish(String(data='hi'))
        _spin(node, 0.02)


ROLES = {f.__name__: f for f in (sink, source, echo, pinger, image_sink, image_source,
                                 first_listener, first_talker)}


# ----------------------------------------------------------------- the front end
def reference():
    python = os.environ.get('ROSREF_PYTHON', str(REPO / '.venv-rosref' / 'bin' / 'python'))
    return python if Path(python).exists() else None


def start(side, role, domain, rate=0):
    env = dict(os.environ, PYTHONUNBUFFERED='1', ROS_DOMAIN_ID=str(domain),
               ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST', BENCH_RATE=str(rate))
    if side == 'real-udp':     # Fast DDS without its shared-memory transport, as labkit talks
        side, env['FASTDDS_BUILTIN_TRANSPORTS'] = 'real', 'UDPv4'

    if side == 'labkit':
        env.update(PYTHONPATH=str(REPO), LABKIT_TIME='live', LABKIT_DDS='on', ROS_DISTRO='jazzy')
        argv = [sys.executable, '-m', 'labkit', 'exec', __file__, '--role', role]
    else:
        env['PYTHONPATH'] = ''
        argv = [reference(), __file__, '--role', role]
    return subprocess.Popen(argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)


def result(proc, timeout=60):
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, err = proc.communicate()
    for line in reversed(out.splitlines()):
        if line.startswith('{'):
            return json.loads(line)
    raise RuntimeError(f'{proc.args[-1]} failed:\n{err[-1500:]}')


def pair(first_side, first_role, second_side, second_role, rate=0):
    """Start the waiting side, then the active one; both results."""
    domain = random.randint(100, 230)
    a = start(first_side, first_role, domain)
    a.stdout.readline()          # 'ready'
    b = start(second_side, second_role, domain, rate)
    return result(a), result(b)


IMAGE_ROWS = (('labkit', 'labkit'), ('labkit', 'real'), ('real', 'real'), ('real', 'labkit'),
              ('real-udp', 'real-udp'))


def image_rows(rounds=1):
    """The 640x480 stream, each row once per round, the rows taking turns (a burst of
    load elsewhere hits a round, not a row). Per row: the median over rounds of each
    round's median and mean frame delay (publish to the subscriber's callback), their
    range, the slowest frame, and the frames lost in each round."""
    print(f'640x480 bgr8 Image at 30 Hz for 3 s, {rounds} interleaved round(s); '
          'frame delay publish -> callback, median over rounds (range):')
    runs = {row: [] for row in IMAGE_ROWS}
    for _ in range(rounds):
        for src, dst in IMAGE_ROWS:
            try:
                got, _ = pair(dst, 'image_sink', src, 'image_source')
            except RuntimeError as e:
                print(f'  {src:>8} -> {dst:<8} failed: {str(e).splitlines()[0]}')
                continue
            if got['delay_ms'] is not None:
                runs[(src, dst)].append(got)
    for (src, dst), row in runs.items():
        if not row:
            continue
        med = [r['delay_ms'] for r in row]
        mean = [r['mean_ms'] for r in row]
        lost = [90 - r['received'] for r in row]
        drops = [r['socket_drops'] or 0 for r in row]
        print(f'  {src:>8} -> {dst:<8} median {statistics.median(med):5.1f} ms '
              f'({min(med):.1f}-{max(med):.1f}), mean {statistics.median(mean):5.1f} ms '
              f'({min(mean):.1f}-{max(mean):.1f}), slowest frame '
              f'{max(r["max_ms"] for r in row):.0f} ms, lost {"/".join(map(str, lost))} of 90, '
              f'reader socket dropped {min(drops)}-{max(drops)}')
    base = runs.get(('real', 'real'))
    for src, dst in (('labkit', 'labkit'), ('labkit', 'real')):
        row = runs.get((src, dst))
        if base and row:
            ratio = [statistics.median(r[key] for r in row) / statistics.median(r[key] for r in base)
                     for key in ('delay_ms', 'mean_ms')]
            print(f'  ratio {src} -> {dst} / real -> real: median {ratio[0]:.2f}, '
                  f'mean {ratio[1]:.2f} (target <= 1, none lost)')


def main():
    if reference() is None:
        print('real rclpy: reference venv not found (make rosref, or set ROSREF_PYTHON)')
        return
    only = sys.argv[sys.argv.index('--only') + 1] if '--only' in sys.argv else None
    rounds = int(sys.argv[sys.argv.index('--rounds') + 1]) if '--rounds' in sys.argv else 3
    if only == 'image':
        return image_rows(rounds)
    print('small messages (std_msgs/String, reliable, keep last 10), received per second, '
          f'{rounds} interleaved rounds (median, min-max):')
    # the rows take turns, so a burst of load elsewhere on the machine hits a round,
    # not one row; the ratios pair rows of the same round. 'paced': labkit publishing
    # no faster than real rclpy did in that round (labkit's publisher is ~16x faster)
    pairs = (('labkit', 'real'), ('real', 'labkit'), ('real', 'real'), ('labkit', 'labkit'),
             ('labkit', 'real', 'paced'))
    rates, published, drops = ({key: [] for key in pairs} for _ in range(3))
    for _ in range(rounds):
        for key in pairs:
            src, dst = key[:2]
            pace = published[('real', 'real')][-1] if len(key) == 3 else 0
            got, sent = pair(dst, 'sink', src, 'source', rate=pace)
            rates[key].append(got['per_s'])
            published[key].append(sent['sent'] / (SECONDS + 1))
            drops[key].append(got['socket_drops'] or 0)
    for key, row in rates.items():
        src, dst = key[:2]
        print(f'  {src:>6} -> {dst:<6} {statistics.median(row):>9,.0f} msgs/s '
              f'({min(row):,.0f}-{max(row):,.0f}; published '
              f'{statistics.median(published[key]):,.0f}/s; reader socket dropped '
              f'{min(drops[key])}-{max(drops[key])})' + (' paced' if len(key) == 3 else ''))
    for key in (('labkit', 'real'), ('real', 'labkit'), ('labkit', 'real', 'paced')):
        ratios = [a / b for a, b in zip(rates[key], rates[('real', 'real')])]
        name = ' -> '.join(key[:2]) + (' paced' if len(key) == 3 else '')
        print(f'  ratio {name} / real -> real: {statistics.median(ratios):.2f} '
              f'({min(ratios):.2f}-{max(ratios):.2f} per round; target >= 1)')
    print('ping-pong round trip (std_msgs/String), median of 300:')
    rtt = {}
    for pinger_side, echo_side in (('labkit', 'real'), ('real', 'labkit'), ('real', 'real'),
                                   ('labkit', 'labkit')):
        _, ping = pair(echo_side, 'echo', pinger_side, 'pinger')
        rtt[(pinger_side, echo_side)] = ping['median_ms']
        print(f'  {pinger_side:>6} <-> {echo_side:<6} {ping["median_ms"]:.2f} ms '
              f'({ping["answered"]}/300 answered)')
    print(f'  ratio labkit <-> real / real <-> real: '
          f'{rtt[("labkit", "real")] / rtt[("real", "real")]:.2f} (target <= 1.5)')
    image_rows(rounds)
    print('process start to first message delivered (listener already running):')

    for talker, listener in (('labkit', 'labkit'), ('labkit', 'real'), ('real', 'real')):
        domain = random.randint(100, 230)
        lis = start(listener, 'first_listener', domain)
        lis.stdout.readline()
        t0 = time.time()
        tal = start(talker, 'first_talker', domain)
        first = result(lis)['first_at']
        tal.kill()
        tal.communicate()
        text = f'{first - t0:.2f} s' if first else 'nothing within 20 s'
        print(f'  {talker:>6} talker -> {listener:<6} listener: {text} (target < 2 s)')


if __name__ == '__main__':
    if '--role' in sys.argv:
        ROLES[sys.argv[sys.argv.index('--role') + 1]]()
    else:
        main()
