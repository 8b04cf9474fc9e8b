"""ros2 daemon start | status | stop, and the node strategy of the graph verbs
(`--spin-time`, `-s/--use-sim-time`, `--no-daemon`), as ros2cli has them.

On a real machine the daemon is a background process per ROS_DOMAIN_ID that keeps a
node alive so `ros2 node list` need not wait for discovery; a verb without
`--no-daemon` starts it when it is not running, and asks it instead of its own
short-lived node. labkit's graph is in-process and always up to date, so there is
nothing to cache: every verb reads the live graph either way. What this noun keeps is
the daemon's state and protocol, honestly: a verb starts the daemon as ros2cli's does,
`--no-daemon` does not, `ros2 daemon stop` stops it (the classic advice "node list
shows nothing: ros2 daemon stop" then costs nothing and changes nothing),
`ros2 daemon status` says which, and `labkit.reset()` leaves no daemon running.
A verb that does not use a running daemon spins its own node for `--spin-time`
seconds before it looks, as ros2cli's DirectNode does; labkit's discovery is
immediate, so only an explicit `--spin-time` is waited for.
"""

from labkit.cli.ros2._base import add_verbs

DEFAULT_TIMEOUT = 0.5          # ros2cli.node.direct.DEFAULT_TIMEOUT (seconds)

_running = set()               # the ROS_DOMAIN_IDs whose daemon runs


def add_arguments(parser, cli_name):
    add_verbs(parser, cli_name, [
        ('start', "Start the daemon if it isn't running", _start_args, start),
        ('status', 'Output the status of the daemon', None, status),
        ('stop', 'Stop the daemon if it is running', None, stop),
    ])


def _domain():
    from labkit.rclpy.context import default_domain_id
    return default_domain_id()


def is_daemon_running():
    return _domain() in _running


def spawn_daemon():
    """Start the daemon of this domain; False if it was already running."""
    if is_daemon_running():
        return False
    _running.add(_domain())
    return True


def shutdown_daemon():
    """Stop the daemon of this domain; False if it was not running."""
    if not is_daemon_running():
        return False
    _running.discard(_domain())
    return True


def reset():
    """labkit.reset(): no daemon is left running."""
    _running.clear()


def _start_args(p):
    p.add_argument('--debug', '-d', action='store_true', help='Print debug messages')


def start(args, io):
    io.print('The daemon has been started' if spawn_daemon() else
             'The daemon is already running')


def status(args, io):
    io.print('The daemon is running' if is_daemon_running() else 'The daemon is not running')


def stop(args, io):
    io.print('The daemon has been stopped' if shutdown_daemon() else
             'The daemon is not running')


# ----------------------------------------------------------------- the verbs' node strategy

def add_strategy_arguments(parser):
    """What ros2cli.node.strategy.add_arguments gives a verb (direct node + daemon flags)."""
    parser.add_argument(
        '--spin-time', type=float, default=None,
        help='Spin time in seconds to wait for discovery (only applies when not using an '
             'already running daemon)')
    parser.add_argument(
        '-s', '--use-sim-time', action='store_true',
        help='Enable ROS simulation time')
    parser.add_argument(
        '--no-daemon', action='store_true',
        help='Do not spawn nor use an already running daemon')


def node_strategy(args):
    """Call at the start of a verb: NodeStrategy's choice of daemon or direct node."""
    use_daemon = not getattr(args, 'no_daemon', False)
    if use_daemon and is_daemon_running():
        return 'daemon'
    if use_daemon:
        spawn_daemon()
    spin_time = getattr(args, 'spin_time', None)
    if spin_time is not None and spin_time > 0:
        from labkit.graph import world
        world.sleep(spin_time)      # the direct node's discovery wait
    return 'direct'


def strategy(add_args, main):
    """(add_arguments, main) of a verb that uses ros2cli's NodeStrategy."""
    def add_arguments(p):
        add_strategy_arguments(p)
        if add_args is not None:
            add_args(p)

    def verb(args, io):
        node_strategy(args)
        return main(args, io)
    verb.__name__ = getattr(main, '__name__', 'verb')
    return add_arguments, verb
