"""`ros2 daemon start|status|stop` and the graph verbs' `--no-daemon` / `--spin-time`
(issue 13): ros2cli's texts, and the daemon's state follows ros2cli's NodeStrategy."""
import pytest

import labkit
from labkit.graph import world


@pytest.fixture(autouse=True)
def _clean():
    labkit.reset()
    yield
    labkit.reset()


def _out(command):
    r = labkit.ros2(command)
    assert r.returncode == 0, r.text()
    return r.stdout


def test_daemon_start_status_stop_texts():
    assert _out('daemon status') == 'The daemon is not running\n'
    assert _out('daemon stop') == 'The daemon is not running\n'
    assert _out('daemon start') == 'The daemon has been started\n'
    assert _out('daemon start') == 'The daemon is already running\n'
    assert _out('daemon status') == 'The daemon is running\n'
    assert _out('daemon stop') == 'The daemon has been stopped\n'
    assert _out('daemon status') == 'The daemon is not running\n'


def test_a_graph_verb_spawns_the_daemon_unless_no_daemon():
    labkit.ros2('run turtlesim turtlesim_node')
    assert _out('node list --no-daemon') == '/turtlesim\n'
    assert _out('daemon status') == 'The daemon is not running\n'
    assert _out('node list') == '/turtlesim\n'         # ros2cli spawns it on the way
    assert _out('daemon status') == 'The daemon is running\n'
    # the usual advice: stopping the daemon changes nothing in what the graph says
    assert _out('daemon stop') == 'The daemon has been stopped\n'
    assert _out('node list') == '/turtlesim\n'
    labkit.reset()
    assert _out('daemon status') == 'The daemon is not running\n'


def test_the_verbs_that_take_strategy_flags_are_ros2clis():
    labkit.ros2('run turtlesim turtlesim_node')
    for command in ('node list', 'node info /turtlesim', 'topic list', 'topic info /rosout',
                    'topic type /rosout', 'topic find std_msgs/msg/String', 'service list',
                    'param list /turtlesim', 'param get /turtlesim background_r',
                    'param describe /turtlesim background_r', 'param dump /turtlesim'):
        r = labkit.ros2(f'{command} --no-daemon --spin-time 0.1 -s')
        assert r.returncode == 0, (command, r.text())
    # ros2service's type/find and ros2topic's pub/hz add no strategy arguments
    r = labkit.ros2('service type /turtlesim/spawn --no-daemon')
    assert r.returncode == 2
    assert r.stderr.endswith('ros2: error: unrecognized arguments: --no-daemon\n')


def test_spin_time_waits_like_a_direct_node():
    before = world.steady_ns()
    _out('node list --no-daemon')                     # labkit's discovery is immediate
    assert world.steady_ns() == before
    _out('topic list --no-daemon --spin-time 2.5')    # an explicit spin time is spent
    assert world.steady_ns() - before == 2_500_000_000
    _out('daemon start')
    _out('topic list --spin-time 2.5')                # a running daemon answers at once
    assert world.steady_ns() - before == 2_500_000_000
