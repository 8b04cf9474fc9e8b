"""ros2 topic hz | bw | delay: the verbs that measure a topic (always background jobs)."""
import copy
import math

from labkit.cli.ros2._base import CliError, CliNode, positive_int
from labkit.cli.ros2.topic import lookup_message_class, spin_forever, wait_message_class

HZ_DEFAULT_WINDOW = 10000
BW_DEFAULT_WINDOW = 100


def _in_job(args):
    return getattr(args, 'in_job', False)


def _sensor_qos():
    from labkit.rclpy.qos import qos_profile_sensor_data
    return copy.copy(qos_profile_sensor_data)


# --------------------------------------------------------------------------- hz

def hz_arguments(p):
    p.add_argument('topic_name', help="Name of the ROS topic to listen to (e.g. '/chatter')")
    p.add_argument('--window', '-w', dest='window_size', type=positive_int,
                   default=HZ_DEFAULT_WINDOW, metavar='WINDOW',
                   help='window size, in # of messages, for calculating rate '
                        f'(default: {HZ_DEFAULT_WINDOW})')
    p.add_argument('--filter', dest='filter_expr', default=None, metavar='EXPR',
                   help='only measure messages matching the specified Python expression')
    p.add_argument('--wall-time', dest='use_wtime', default=False, action='store_true',
                   help='calculates rate using wall time which can be helpful when clock is '
                        'not published during simulation')
    p.set_defaults(_background=lambda a: True)


class RateMeter:
    """Message arrival intervals over a window (ros2topic hz's ROSTopicHz, one topic)."""

    def __init__(self, clock, window_size):
        self.clock = clock
        self.window_size = window_size
        self.msg_t0 = -1
        self.msg_tn = 0
        self.times = []
        self.last_printed_tn = 0

    def on_message(self, now_ns):
        if now_ns == 0:
            self.times = []
            return
        if self.msg_t0 < 0 or self.msg_t0 > now_ns:
            self.msg_t0 = now_ns
            self.msg_tn = now_ns
            self.times = []
        else:
            self.times.append(now_ns - self.msg_tn)
            self.msg_tn = now_ns
        if len(self.times) > self.window_size:
            self.times.pop(0)

    def report(self):
        """The two lines to print, or None when there is nothing new (once a second)."""
        if not self.times:
            return None
        if self.last_printed_tn == 0:
            self.last_printed_tn = self.msg_tn
            return None
        if self.msg_tn < self.last_printed_tn + 1e9:
            return None
        n = len(self.times)
        mean = sum(self.times) / n
        rate = 1. / mean if mean > 0. else 0
        std_dev = math.sqrt(sum((x - mean) ** 2 for x in self.times) / n)
        self.last_printed_tn = self.msg_tn
        return ('average rate: %.3f\n\tmin: %.3fs max: %.3fs std dev: %.5fs window: %s'
                % (rate * 1e9, min(self.times) * 1e-9, max(self.times) * 1e-9,
                   std_dev * 1e-9, n))


def hz(args, io):
    filter_fn = None
    if args.filter_expr:
        code = compile(args.filter_expr, '<filter>', 'eval')
        filter_fn = lambda m: eval(code, {}, {'m': m})  # noqa: E731
    with CliNode(default_context=_in_job(args)) as node:
        cls = wait_message_class(node, args.topic_name, io)
        if cls is None:
            return
        if args.use_wtime:
            from labkit.rclpy.clock import Clock, ClockType
            clock = Clock(clock_type=ClockType.SYSTEM_TIME)
        else:
            clock = node.get_clock()
        meter = RateMeter(clock, args.window_size)
        arrived = {}            # id(message) -> when it reached the subscription

        def callback(msg):
            stamp = arrived.pop(id(msg), None)
            if filter_fn is None or filter_fn(msg):
                # the time it arrived, as the middleware stamps a reception: a callback
                # that runs late for several queued messages must not see them as a burst
                meter.on_message(stamp if stamp is not None else clock.now().nanoseconds)

        sub = node.create_subscription(cls, args.topic_name, callback,
                                       _sensor_qos())
        _stamp_arrivals(sub, clock, arrived)
        try:
            while node.ok():
                node.spin_once(timeout_sec=1.0)
                line = meter.report()
                if line:
                    io.print(line)
        except Exception:
            if node.ok():
                raise



def _stamp_arrivals(sub, clock, arrived):
    """Note the reception time of every message the subscription is handed."""
    endpoint = getattr(sub, '_endpoint', None)
    deliver = getattr(endpoint, 'sink', None)
    if deliver is None:
        return

    def sink(msg):
        if len(arrived) > 1000:         # messages the queue dropped (KEEP_LAST) never come
            arrived.clear()
        arrived[id(msg)] = clock.now().nanoseconds
        deliver(msg)
    from labkit.graph.registry import GRAPH
    with GRAPH.lock:                    # publishers hold the sinks they matched: renew them
        endpoint.sink = sink
        GRAPH._rematch(endpoint.name)


# --------------------------------------------------------------------------- bw

def bw_arguments(p):
    p.add_argument('topic', help='Topic name to monitor for bandwidth utilization')
    p.add_argument('--window', '-w', type=positive_int, default=BW_DEFAULT_WINDOW,
                   metavar='WINDOW',
                   help='maximum window size, in # of messages, for calculating rate '
                        f'(default: {BW_DEFAULT_WINDOW})')
    p.set_defaults(_background=lambda a: True)


def _size_units(num_bytes, unit):
    if unit == 'B':
        return f'{num_bytes:.0f} B'
    if unit == 'KB':
        return f'{num_bytes / 1000:.2f} KB'
    return f'{num_bytes / 1000 / 1000:.2f} MB'


class Bandwidth:
    """Received bytes over a window of messages (ros2topic bw's ROSTopicBandwidth)."""

    def __init__(self, clock, window_size):
        self.clock = clock
        self.window_size = window_size
        self.sizes = []
        self.times = []

    def on_message(self, size):
        self.times.append(self.clock.now().nanoseconds)
        self.sizes.append(size)
        if len(self.times) > self.window_size:
            self.times.pop(0)
            self.sizes.pop(0)

    def report(self):
        if len(self.times) < 2:
            return None
        n = len(self.times)
        tn = self.clock.now().nanoseconds
        t0 = self.times[0]
        if tn <= t0:
            self.times, self.sizes = [], []
            return None
        total = sum(self.sizes)
        bytes_per_s = total / ((tn - t0) * 1.e-9)
        unit = 'B' if bytes_per_s < 1000 else 'KB' if bytes_per_s < 1000000 else 'MB'
        bw_, mean, min_s, max_s = (_size_units(v, unit) for v in
                                   (bytes_per_s, total / n, min(self.sizes), max(self.sizes)))
        return f'{bw_}/s from {n} messages\n\tMessage size mean: {mean} min: {min_s} max: {max_s}'


def bw(args, io):
    with CliNode(default_context=_in_job(args)) as node:
        # Humble's bw always shows this first: its fresh node has not yet discovered the topic.
        io.print(f'WARNING: topic [{args.topic}] does not appear to be published yet')
        cls = lookup_message_class(node, args.topic)
        while cls is None and node.ok():
            node.spin_once(timeout_sec=0.1)
            cls = lookup_message_class(node, args.topic)
        if cls is None:
            return
        from labkit.interfaces import serialize
        meter = Bandwidth(node.get_clock(), args.window)
        node.create_subscription(cls, args.topic, lambda m: meter.on_message(len(serialize(m))),
                                 _sensor_qos())
        io.print(f'Subscribed to [{args.topic}]')

        def tick():
            line = meter.report()
            if line:
                io.print(line)

        node.create_timer(1.0, tick)
        spin_forever(node)


# --------------------------------------------------------------------------- delay

def delay_arguments(p):
    p.add_argument('topic', help='Topic name to calculate the delay for')
    p.add_argument('--window', '-w', type=positive_int, default=HZ_DEFAULT_WINDOW,
                   help='window size, in # of messages, for calculating rate, string to '
                        f'(default: {HZ_DEFAULT_WINDOW})')
    p.set_defaults(_background=lambda a: True)


class DelayMeter:
    """now - header.stamp over a window of messages (ros2topic delay's ROSTopicDelay)."""

    def __init__(self, window_size):
        self.window_size = window_size
        self.msg_t0 = -1
        self.msg_tn = 0
        self.last_msg_tn = 0
        self.delays = []

    def on_message(self, now_ns, stamp_ns):
        if now_ns == 0:
            self.delays = []
            return
        if self.msg_t0 < 0 or self.msg_t0 > now_ns:
            self.msg_t0 = self.msg_tn = now_ns
            self.delays = []
        else:
            self.delays.append(now_ns - stamp_ns)
            self.msg_tn = now_ns
        if len(self.delays) > self.window_size:
            self.delays.pop(0)

    def report(self):
        if not self.delays:
            return None
        if self.msg_tn == self.last_msg_tn:
            return 'no new messages'
        n = len(self.delays)
        mean = sum(self.delays) / n
        std_dev = math.sqrt(sum((x - mean) ** 2 for x in self.delays) / n)
        self.last_msg_tn = self.msg_tn
        return ('average delay: %.3f\n\tmin: %.3fs max: %.3fs std dev: %.5fs window: %s'
                % (mean * 1e-9, min(self.delays) * 1e-9, max(self.delays) * 1e-9,
                   std_dev * 1e-9, n))


def delay(args, io):
    with CliNode(default_context=_in_job(args)) as node:
        cls = wait_message_class(node, args.topic, io)
        if cls is None:
            return
        clock = node.get_clock()
        meter = DelayMeter(args.window)

        def callback(msg):
            if not hasattr(msg, 'header'):
                raise CliError('msg does not have header')
            stamp = msg.header.stamp
            meter.on_message(clock.now().nanoseconds, stamp.sec * 10**9 + stamp.nanosec)

        node.create_subscription(cls, args.topic, callback, _sensor_qos())

        def tick():
            line = meter.report()
            if line:
                io.print(line)

        node.create_timer(1.0, tick)
        spin_forever(node)
