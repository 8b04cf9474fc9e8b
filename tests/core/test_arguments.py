import pytest

from labkit.graph import arguments
from labkit.rclpy.exceptions import RCLError, UnknownROSArgsError


def test_parse_rules_and_non_ros_args():
    args = arguments.parse(['prog', 'a', '--ros-args', '-r', '__node:=t2', '--remap',
                            'chatter:=/foo', '-p', 'rate:=2.5', '-p', 'talker:names:=[a, b]',
                            '--log-level', 'debug', '--', 'b'])
    assert args.non_ros_args == ['prog', 'a', 'b']
    assert [(r.kind, r.match, r.replacement) for r in args.remaps] == [
        (arguments.NODENAME, None, 't2'), (arguments.TOPIC | arguments.SERVICE, 'chatter', '/foo')]
    assert args.cli_params == [('/**', 'rate', 2.5), ('talker', 'names', ['a', 'b'])]
    assert args.log_levels == {'': 10}


@pytest.mark.parametrize('text, value', [
    ('1', 1), ('1.5', 1.5), ('true', True), ('False', False), ('hello', 'hello'),
    ('[1, 2]', [1, 2]), ("'7'", '7'),
])
def test_param_values_are_yaml_typed(text, value):
    assert arguments.parse(['--ros-args', '-p', f'x:={text}']).cli_params == [('/**', 'x', value)]


@pytest.mark.parametrize('argv, text', [
    (['--ros-args', '-r'], "Couldn't parse trailing -r flag. No remap rule found."),
    (['--ros-args', '-p'], "Couldn't parse trailing -p flag. No parameter override rule found."),
    (['--ros-args', '--params-file'],
     "Couldn't parse trailing --params-file flag. No file path provided."),
    (['--ros-args', '--log-level'],
     "Couldn't parse trailing log level flag: '--log-level'. No log level provided."),
    (['--ros-args', '-e'], "Couldn't parse trailing -e flag. No enclave path provided."),
])
def test_trailing_flags(argv, text):
    with pytest.raises(arguments.ArgumentError) as exc:
        arguments.parse(argv)
    assert str(exc.value) == text


def test_bad_rules():
    with pytest.raises(arguments.ArgumentError) as exc:
        arguments.parse(['--ros-args', '-r', 'nocolon'])
    assert str(exc.value).startswith("Couldn't parse remap rule: '-r nocolon'. Error: ")
    with pytest.raises(arguments.ArgumentError) as exc:
        arguments.parse(['--ros-args', '--log-level', 'loud'])
    assert str(exc.value).startswith("Couldn't parse log level: '--log-level loud'.")


def test_unknown_ros_args_are_reported(rclpy):
    from labkit.rclpy.context import Context
    ctx = Context()
    with pytest.raises(UnknownROSArgsError) as exc:
        ctx.init(['prog', '--ros-args', '--bogus'])
    assert str(exc.value) == "['--bogus']"
    with pytest.raises(RCLError) as exc:
        Context().init(['prog', '--ros-args', '-r'])
    assert str(exc.value).startswith('failed to initialize rcl: ')


def test_remove_ros_args(rclpy):
    assert rclpy.remove_ros_args(['p', '--ros-args', '-r', 'a:=b', '--', 'x']) == ['p', 'x']
    assert rclpy.utilities.remove_ros_args(['p', 'y']) == ['p', 'y']


def test_global_remaps_node_name_namespace_and_topics(virtual, msgs):
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    rclpy.init(args=['prog', '--ros-args', '-r', '__node:=renamed', '-r', '__ns:=/space',
                     '-r', 'chatter:=talk', '-r', 'other:chatter:=never'])
    node = Node('talker')
    assert node.get_fully_qualified_name() == '/space/renamed'
    pub = node.create_publisher(msgs.String, 'chatter', 10)
    assert pub.topic_name == '/space/talk'
    assert node.resolve_topic_name('chatter', only_expand=True) == '/space/chatter'
    # node-local arguments win, and global ones can be ignored
    local = Node('talker', cli_args=['-r', '__node:=local'])
    assert local.get_name() == 'local'
    bare = Node('talker', use_global_arguments=False)
    assert bare.get_fully_qualified_name() == '/talker'
    assert bare.create_publisher(msgs.String, 'chatter', 10).topic_name == '/chatter'


def test_node_specific_rules(virtual):
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    rclpy.init(args=['--ros-args', '-r', 'a:__node:=a2', '-r', 'b:x:=y'])
    assert Node('a').get_name() == 'a2'
    b = Node('b')
    assert b.get_name() == 'b'
    assert b.resolve_topic_name('x') == '/y'
    assert Node('c').resolve_topic_name('x') == '/x'


def test_parameter_overrides_files_then_cli(virtual, tmp_path):
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    f = tmp_path / 'p.yaml'
    f.write_text('/**:\n  ros__parameters:\n    common: 1\n    rate: 5\n'
                 'talker:\n  ros__parameters:\n    rate: 10\n    nested:\n      a: x\n'
                 '/ns/*:\n  ros__parameters:\n    only_ns: true\n')
    rclpy.init(args=['--ros-args', '--params-file', str(f), '-p', 'talker:rate:=20'])
    talker = Node('talker', start_parameter_services=False)
    assert talker._parameter_overrides_from_args() == {
        'common': 1, 'rate': 20, 'nested.a': 'x'}
    other = Node('other', namespace='/ns', start_parameter_services=False)
    assert other._parameter_overrides_from_args() == {'common': 1, 'rate': 5, 'only_ns': True}
    local = Node('talker', cli_args=['-p', 'rate:=30'], start_parameter_services=False)
    assert local._parameter_overrides_from_args()['rate'] == 30


def test_log_level_argument(virtual, capfd):
    import labkit.rclpy as rclpy
    from labkit.rclpy.node import Node
    rclpy.init(args=['--ros-args', '--log-level', 'talker:=debug'])
    Node('talker').get_logger().debug('shown')
    Node('other').get_logger().debug('hidden')
    err = capfd.readouterr().err
    assert '[DEBUG] [1704067200.000000000] [talker]: shown' in err
    assert 'hidden' not in err
