"""ros2 node/topic/service/action/param verbs on a known graph, in virtual time."""
import pytest

import labkit
from labkit import process
from labkit.cli.ros2 import run_command

pytestmark = pytest.mark.skipif(
    not hasattr(__import__('labkit.rclpy').rclpy, 'create_node'),
    reason='the rclpy core is not there yet')


# --------------------------------------------------------------------------- the graph

def robot_main(args=None):
    """A node with one of everything: /chatter pub, /cmd sub, a service, an action, params."""
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    from labkit.rclpy.action import ActionServer
    from labkit.rclpy.node import Node
    String = get_type('std_msgs/msg/String')
    Twist = get_type('geometry_msgs/msg/Twist')
    AddTwoInts = get_type('example_interfaces/srv/AddTwoInts')
    Fibonacci = get_type('example_interfaces/action/Fibonacci')
    Descriptor = get_type('rcl_interfaces/msg/ParameterDescriptor')

    rclpy.init(args=args)
    node = Node('robot', namespace='/lab')
    pub = node.create_publisher(String, 'chatter', 10)
    count = [0]

    def tick():
        count[0] += 1
        pub.publish(String(data=f'hello {count[0]}'))

    node.create_timer(0.1, tick)
    node.create_subscription(Twist, 'cmd', lambda m: None, 10)

    def add(request, response):
        response.sum = request.a + request.b
        return response

    node.create_service(AddTwoInts, 'add_two_ints', add)

    def execute(goal_handle):
        seq = [0, 1]
        for i in range(1, goal_handle.request.order):
            seq.append(seq[i] + seq[i - 1])
            feedback = Fibonacci.Feedback(sequence=seq)
            goal_handle.publish_feedback(feedback)
        goal_handle.succeed()
        return Fibonacci.Result(sequence=seq)

    ActionServer(node, Fibonacci, 'fibonacci', execute)
    node.declare_parameter('speed', 86)
    node.declare_parameter('label', 'robot')
    node.declare_parameter('gains.p', 1.5)
    node.declare_parameter('frozen', True, Descriptor(read_only=True, description='fixed'))
    try:
        rclpy.spin(node)
    except Exception:
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


@pytest.fixture
def robot():
    proc = process.start(main=robot_main, name='robot')
    yield proc
    labkit.reset()


def ok(command):
    result = run_command(command)
    assert result.returncode == 0, (result.stdout, result.stderr)
    return result.stdout


# --------------------------------------------------------------------------- node

def test_node_list_and_hidden(robot):
    assert ok('node list') == '/lab/robot\n'
    assert ok('node list -c') == '1\n'
    everything = ok('node list -a').splitlines()
    assert '/lab/robot' in everything
    assert any(name.startswith('/_ros2cli_') for name in everything)


def test_node_info_sections(robot):
    out = ok('node info /lab/robot')
    assert out.startswith('/lab/robot\n  Subscribers:\n    /lab/cmd: geometry_msgs/msg/Twist\n'
                          '  Publishers:\n')
    assert '    /lab/chatter: std_msgs/msg/String\n' in out
    assert '    /parameter_events: rcl_interfaces/msg/ParameterEvent\n' in out
    assert '  Service Servers:\n    /lab/add_two_ints: example_interfaces/srv/AddTwoInts\n' in out
    assert '    /lab/robot/list_parameters: rcl_interfaces/srv/ListParameters\n' in out
    assert out.endswith('  Action Servers:\n'
                        '    /lab/fibonacci: example_interfaces/action/Fibonacci\n'
                        '  Action Clients:\n\n')
    assert '_action' not in out
    hidden = ok('node info /lab/robot --include-hidden')
    assert '/lab/fibonacci/_action/send_goal' in hidden


def test_node_info_unknown(robot):
    r = run_command('node info /nobody')
    assert (r.returncode, r.stdout, r.stderr) == (1, '', "Unable to find node '/nobody'\n")


# --------------------------------------------------------------------------- topic

def test_topic_list(robot):
    lines = ok('topic list').splitlines()
    assert lines == sorted(lines)
    assert {'/lab/chatter', '/lab/cmd', '/parameter_events', '/rosout'} <= set(lines)
    assert not any('_action' in line for line in lines)
    typed = ok('topic list -t')
    assert '/lab/chatter [std_msgs/msg/String]\n' in typed
    assert int(ok('topic list -c')) == len(lines)
    assert '/lab/fibonacci/_action/status' in ok('topic list --include-hidden-topics')


def test_topic_info_type_find(robot):
    assert ok('topic info /lab/chatter') == \
        'Type: std_msgs/msg/String\nPublisher count: 1\nSubscription count: 0\n'
    assert ok('topic type /lab/cmd') == 'geometry_msgs/msg/Twist\n'
    assert run_command('topic type /nope').returncode == 1
    assert ok('topic find geometry_msgs/msg/Twist') == '/lab/cmd\n'
    r = run_command('topic info /nope')
    assert (r.returncode, r.stderr) == (1, "Unknown topic '/nope'\n")
    verbose = ok('topic info -v /lab/chatter')
    assert verbose.startswith('Type: std_msgs/msg/String\n\nPublisher count: 1\n\n')
    assert 'Node name: robot' in verbose


def test_topic_echo_once(robot):
    out = ok('topic echo --once /lab/chatter')
    assert out.startswith("data: hello ")
    assert out.endswith("\n---\n") and out.count('---') == 1
    assert ok('topic echo --once /lab/chatter --field data').endswith("\n---\n")
    csv = ok('topic echo --once /lab/chatter --csv')
    assert csv.startswith('hello ') and csv.count('\n') == 1


def test_topic_echo_unknown_topic(robot):
    r = run_command('topic echo --once /nope')
    assert r.returncode == 1
    assert r.stdout == 'WARNING: topic [/nope] does not appear to be published yet\n'
    assert r.stderr == 'Could not determine the type for the passed topic\n'
    r = run_command('topic echo --once /lab/chatter std_msgs/msg/Nope')
    assert (r.returncode, r.stderr) == (1, 'The passed message type is invalid\n')


def test_topic_pub_once_reaches_a_subscriber(robot):
    got = []
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    Twist = get_type('geometry_msgs/msg/Twist')
    rclpy.init()
    node = rclpy.create_node('watcher')
    node.create_subscription(Twist, '/lab/cmd', got.append, 10)
    r = run_command('topic pub --once /lab/cmd geometry_msgs/msg/Twist "{linear: {x: 2.0}}"')
    assert r.returncode == 0, r.stderr
    assert r.stdout == (
        'publisher: beginning loop\n'
        'publishing #1: geometry_msgs.msg.Twist(linear=geometry_msgs.msg.Vector3(x=2.0, y=0.0, '
        'z=0.0), angular=geometry_msgs.msg.Vector3(x=0.0, y=0.0, z=0.0))\n\n')
    rclpy.spin_once(node, timeout_sec=0.5)
    assert [m.linear.x for m in got] == [2.0]
    node.destroy_node()
    rclpy.shutdown()


def test_topic_pub_bad_values(robot):
    r = run_command('topic pub --once /x std_msgs/msg/String "[1, 2]"')
    assert (r.returncode, r.stderr) == (
        1, 'The passed value needs to be a dictionary in YAML format\n')
    r = run_command('topic pub --once -w 0 /x std_msgs/String "{nope: 1}"')
    assert r.returncode == 1 and r.stderr.startswith('Failed to populate field: ')


# --------------------------------------------------------------------------- service

def test_service_list_type_find(robot):
    lines = ok('service list').splitlines()
    assert '/lab/add_two_ints' in lines and '/lab/robot/get_parameters' in lines
    assert not any('_action' in line for line in lines)
    assert '/lab/add_two_ints [example_interfaces/srv/AddTwoInts]' in ok('service list -t')
    assert ok('service type /lab/add_two_ints') == 'example_interfaces/srv/AddTwoInts\n'
    assert ok('service find example_interfaces/srv/AddTwoInts') == '/lab/add_two_ints\n'


def test_service_call(robot):
    out = ok('service call /lab/add_two_ints example_interfaces/srv/AddTwoInts "{a: 2, b: 3}"')
    assert out == (
        'requester: making request: example_interfaces.srv.AddTwoInts_Request(a=2, b=3)\n\n'
        'response:\nexample_interfaces.srv.AddTwoInts_Response(sum=5)\n\n')
    r = run_command('service call /lab/add_two_ints nope/srv/X')
    assert (r.returncode, r.stderr) == (1, 'The passed service type is invalid\n')


def test_service_call_waits_then_reports_in_virtual_time():
    r = run_command('service call /absent std_srvs/srv/Empty')
    assert r.returncode == 1
    assert r.stdout == 'waiting for service to become available...\n'
    assert r.stderr.startswith('labkit: ')


# --------------------------------------------------------------------------- action

def test_action_list_info(robot):
    assert ok('action list') == '/lab/fibonacci\n'
    assert ok('action list -t') == '/lab/fibonacci [example_interfaces/action/Fibonacci]\n'
    assert ok('action info /lab/fibonacci') == \
        'Action: /lab/fibonacci\nAction clients: 0\nAction servers: 1\n    /lab/robot\n'


def test_action_send_goal_with_feedback(robot):
    out = ok('action send_goal /lab/fibonacci example_interfaces/action/Fibonacci '
             '"{order: 3}" --feedback')
    lines = out.split('\n')
    assert lines[:3] == ['Waiting for an action server to become available...',
                         'Sending goal:', '     order: 3']
    accepted = [line for line in lines if line.startswith('Goal accepted with ID: ')][0]
    assert len(accepted.split(': ')[1]) == 32
    assert 'Feedback:\n    sequence:\n- 0\n- 1\n- 1\n' in out
    assert out.endswith('Result:\n    sequence:\n- 0\n- 1\n- 1\n- 2\n\n'
                        'Goal finished with status: SUCCEEDED\n')


# --------------------------------------------------------------------------- param

def test_param_list_get(robot):
    out = ok('param list')
    assert out.startswith('/lab/robot:\n')
    assert '  speed\n' in out and '  gains.p\n' in out and '  use_sim_time\n' in out
    assert ok('param list /lab/robot --param-type').count('(type: ') >= 4
    assert '  speed (type: integer)\n' in ok('param list /lab/robot --param-type')
    assert ok('param get /lab/robot speed') == 'Integer value is: 86\n'
    assert ok('param get /lab/robot label') == 'String value is: robot\n'
    assert ok('param get /lab/robot gains.p') == 'Double value is: 1.5\n'
    assert ok('param get /lab/robot frozen') == 'Boolean value is: True\n'
    r = run_command('param get /lab/robot nope')  # Humble: an empty answer, so this line
    assert (r.returncode, r.stdout, r.stderr) == (1, '', 'Parameter not set\n')
    r = run_command('param get /nobody speed')
    assert (r.returncode, r.stderr) == (1, 'Node not found\n')


def test_param_set_describe_dump(robot, tmp_path):
    assert ok('param set /lab/robot speed 90') == 'Set parameter successful\n'
    assert ok('param get /lab/robot speed') == 'Integer value is: 90\n'
    r = run_command('param set /lab/robot frozen false')
    assert r.returncode == 0 and r.stderr.startswith('Setting parameter failed')
    assert ok('param describe /lab/robot frozen') == (
        'Parameter name: frozen\n  Type: boolean\n  Description: fixed\n  Constraints:\n'
        '    Read only: true\n')
    dump = ok('param dump /lab/robot')
    assert dump.startswith('/lab/robot:\n  ros__parameters:\n    frozen: true\n'
                           '    gains:\n      p: 1.5\n    label: robot\n    speed: 90\n')
    path = tmp_path / 'robot.yaml'
    path.write_text(dump.replace('speed: 90', 'speed: 7'))
    r = run_command(f'param load /lab/robot {path}')
    assert 'Set parameter speed successful\n' in r.stdout
    assert 'Set parameter frozen failed' in r.stderr
    assert ok('param get /lab/robot speed') == 'Integer value is: 7\n'


# --------------------------------------------------------------------------- jobs / run

def test_run_job_and_duplicates():
    job = labkit.ros2('run demo_nodes_cpp talker')
    assert job.state == 'running' and job.returncode is None
    assert ok('node list') == '/talker\n'
    again = labkit.ros2('run demo_nodes_cpp talker')
    assert again.returncode == 0 and 'already running' in again.stdout
    assert ok('node list') == '/talker\n'
    listing = ok('jobs')
    assert listing == f'[{job.id}] {job.pid} running ros2 run demo_nodes_cpp talker\n'
    labkit.sleep(2.5)
    assert any("Publishing: 'Hello World: 1'" in line for line in job.output)
    assert any("Publishing: 'Hello World: 2'" in line for line in job.output)
    ok(f'jobs stop {job.id}')
    assert job.state == 'stopped'
    assert ok('node list') == ''
    assert ok('jobs') == ''


def test_talker_listener():
    talker = labkit.ros2('run demo_nodes_cpp talker')
    listener = labkit.ros2('run demo_nodes_cpp listener')
    labkit.sleep(3.0)
    assert any('I heard: [Hello World: 1]' in line for line in listener.output)
    assert any('[talker]' in line for line in talker.output)
    ok('jobs stop all')


def test_minimal_publisher_subscriber():
    pub = labkit.ros2('run examples_rclcpp_minimal_publisher publisher_member_function')
    sub = labkit.ros2('run examples_rclcpp_minimal_subscriber subscriber_member_function')
    assert ok('node list') == '/minimal_publisher\n/minimal_subscriber\n'
    labkit.sleep(1.2)
    assert any("Publishing: 'Hello, world! 0'" in line for line in pub.output)
    assert any("I heard: 'Hello, world! 0'" in line for line in sub.output)
    ok('jobs stop all')


def test_echo_and_hz_jobs(robot):
    echo = labkit.ros2('topic echo /lab/chatter')
    hz = labkit.ros2('topic hz /lab/chatter')
    assert echo.returncode is None and hz.returncode is None
    labkit.sleep(2.05)
    assert echo.output[0].startswith('data: hello') and echo.output[1] == '---'
    assert 'average rate: 10.000' in hz.output
    assert '\tmin: 0.100s max: 0.100s std dev: 0.00000s window: 11' in hz.output
    ok('jobs stop all')
    assert echo.state == 'stopped'


def test_bw_job(robot):
    bw = labkit.ros2('topic bw /lab/chatter')
    labkit.sleep(1.5)
    assert bw.output[:2] == ['WARNING: topic [/lab/chatter] does not appear to be published yet',
                             'Subscribed to [/lab/chatter]']
    # 16-byte CDR messages, 9 of them between t=0.1 s and the first report at t=1 s
    assert bw.output[2] == '160 B/s from 9 messages'
    assert bw.output[3] == '\tMessage size mean: 16 B min: 16 B max: 16 B'
    assert bw.output[3].startswith('\tMessage size mean: ')
    bw.stop()


def test_pub_rate_job(robot):
    got = []
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    rclpy.init()
    node = rclpy.create_node('watcher')
    node.create_subscription(get_type('std_msgs/msg/String'), '/said', got.append, 10)
    job = labkit.ros2('topic pub -r 2 /said std_msgs/msg/String "{data: hi}"')
    assert job.returncode is None
    labkit.sleep(1.9)
    for _ in range(10):
        rclpy.spin_once(node, timeout_sec=0)
    assert [m.data for m in got] == ['hi'] * 4
    assert job.output[0] == 'publisher: beginning loop'
    job.stop()
    node.destroy_node()
    rclpy.shutdown()


def test_topic_list_verbose(robot):
    out = ok('topic list -v')
    pubs, subs = out.split('\n\n')[:2]
    assert pubs.startswith('Published topics:\n')
    assert ' * /lab/chatter [std_msgs/msg/String] 1 publisher\n' in pubs + '\n'
    assert subs.startswith('Subscribed topics:\n')
    assert ' * /lab/cmd [geometry_msgs/msg/Twist] 1 subscriber' in subs


def zeta_main(args=None):
    import labkit.rclpy as rclpy
    rclpy.init(args=args)
    node = rclpy.create_node('zeta', namespace='/a')
    node.declare_parameter('k', 1)
    try:
        rclpy.spin(node)
    except Exception:
        pass


def test_param_list_sorts_nodes_like_ros2param(robot):
    process.start(main=zeta_main, name='zeta')
    out = ok('param list')
    # ('robot', '/lab') sorts before ('zeta', '/a'): base names first
    assert out.index('/lab/robot:') < out.index('/a/zeta:')


def test_param_verbs_on_a_node_that_does_not_spin(robot):
    import labkit.rclpy as rclpy
    rclpy.init()
    mute = rclpy.create_node('mute')
    mute.declare_parameter('k', 1)
    r = run_command('param list')
    assert "Exception while calling service of node '/mute': None\n" == r.stderr
    assert '/lab/robot:' in r.stdout
    r = run_command('param get /mute k')
    assert r.returncode == 1 and r.stderr.startswith('labkit: gave up after 60 s')
    mute.destroy_node()
    rclpy.shutdown()


def test_service_call_rate_is_a_job(robot):
    job = labkit.ros2('service call -r 2 /lab/add_two_ints example_interfaces/srv/AddTwoInts '
                      '"{a: 1, b: 1}"')
    assert job.returncode is None
    labkit.sleep(1.2)
    responses = [line for line in job.output if line.endswith('(sum=2)')]
    assert len(responses) == 3  # t = 0, 0.5, 1.0
    job.stop()


def test_a_job_that_fails_at_once_ends_like_a_short_command():
    r = labkit.ros2('topic echo /nothing_here')
    assert (r.returncode, r.stdout, r.stderr) == (
        1, 'WARNING: topic [/nothing_here] does not appear to be published yet\n',
        'Could not determine the type for the passed topic\n')
    r = labkit.ros2('topic pub /x std_msgs/msg/Nope')
    assert (r.returncode, r.stderr) == (1, 'The passed message type is invalid\n')
    assert run_command('jobs').stdout == ''


def test_a_job_that_fails_later_reports_in_its_output(robot):
    job = labkit.ros2('topic echo /lab/chatter --field nope')
    assert job.returncode is None
    labkit.sleep(0.5)
    assert job.state == 'done' and job.returncode == 1
    assert job.output[-1].startswith("Invalid field 'nope': ")


def test_jobs_listing_and_stop_all():
    a = labkit.ros2('run demo_nodes_cpp talker')
    b = labkit.ros2('run --new demo_nodes_cpp talker')
    assert a.id != b.id
    assert ok('jobs').splitlines() == [a.line(), b.line()]
    r = run_command('jobs stop 999')
    assert (r.returncode, r.stderr) == (1, 'ros2 jobs: no such job: 999\n')
    stopped = ok('jobs stop all')
    assert stopped.splitlines() == [a.line(), b.line()]
    assert a.state == b.state == 'stopped'
    assert ok('jobs') == '' and ok('node list') == ''


def stamped_main(args=None):
    """Publishes geometry_msgs/PointStamped stamped 0.25 s in the past, at 10 Hz."""
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    from labkit.rclpy.duration import Duration
    PointStamped = get_type('geometry_msgs/msg/PointStamped')
    rclpy.init(args=args)
    node = rclpy.create_node('stamper')
    pub = node.create_publisher(PointStamped, 'stamped', 10)

    def tick():
        msg = PointStamped()
        msg.header.stamp = (node.get_clock().now() - Duration(seconds=0.25)).to_msg()
        pub.publish(msg)

    node.create_timer(0.1, tick)
    try:
        rclpy.spin(node)
    except Exception:
        pass


def test_topic_delay_job():
    process.start(main=stamped_main, name='stamper')
    job = labkit.ros2('topic delay /stamped')
    labkit.sleep(1.05)
    assert job.output == ['average delay: 0.250',
                          '\tmin: 0.250s max: 0.250s std dev: 0.00000s window: 8']
    job.stop()


def arrays_main(args=None):
    import labkit.rclpy as rclpy
    from labkit.interfaces import get_type
    Int32MultiArray = get_type('std_msgs/msg/Int32MultiArray')
    rclpy.init(args=args)
    node = rclpy.create_node('arrays')
    pub = node.create_publisher(Int32MultiArray, 'numbers', 10)
    node.create_timer(0.1, lambda: pub.publish(Int32MultiArray(data=list(range(200)))))
    try:
        rclpy.spin(node)
    except Exception:
        pass


def test_echo_array_options():
    process.start(main=arrays_main, name='arrays')
    full = ok('topic echo --once /numbers --full-length')
    short = ok('topic echo --once /numbers')
    tiny = ok('topic echo --once /numbers -l 3')
    assert full.count('\n') > short.count('\n') > tiny.count('\n')
    assert "'...'" in tiny and "'...'" not in full
    # a selected non-message field prints as Python prints it (Humble does the same)
    field = ok('topic echo --once /numbers --field data')
    assert field.startswith("array('i', [0, 1, 2,") and field.endswith('])\n---\n')
    no_arr = ok('topic echo --once /numbers --no-arr')
    assert 'data: ' in no_arr and '- 199' not in no_arr


def test_duplicate_node_names_warn(robot):
    process.start(main=robot_main, name='robot2')
    r = run_command('node list')
    assert r.stdout == '/lab/robot\n/lab/robot\n'
    assert r.stderr == ('WARNING: Be aware that are nodes in the graph that share an exact name, '
                        'this can have unintended side effects.\n')
    r = run_command('node info /lab/robot')
    assert r.stderr == ('There are 2 nodes in the graph with the exact name "/lab/robot". '
                        'You are seeing information about only one of them.\n')
    assert r.stdout.startswith('/lab/robot\n  Subscribers:\n')


def test_empty_graph_still_has_the_cli_topics():
    # ros2cli's own node publishes these, so a bare `ros2 topic list` shows them
    assert ok('topic list') == '/parameter_events\n/rosout\n'
    assert ok('node list') == ''


def test_demo_nodes_py_talker_prints_the_python_way():
    job = labkit.ros2('run demo_nodes_py talker')
    labkit.sleep(1.0)
    assert job.output[-1].endswith('[talker]: Publishing: "Hello World: 0"')
    job.stop()
