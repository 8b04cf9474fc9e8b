"""One small system written three times (Python, XML, YAML) starts the same graph; each
front-end includes the others; every `$(...)` substitution; bad files answer in launch's
words; `ros2 launch <package> x.launch.xml --show-args` and `name:=value` (issue 13)."""
import os
import textwrap
import xml.etree.ElementTree as ET

import pytest

import labkit
from labkit.launch import frontend

PY = {
    'pond.launch.py': '''\
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
        from launch.conditions import IfCondition, UnlessCondition
        from launch.launch_description_sources import AnyLaunchDescriptionSource
        from launch.substitutions import (LaunchConfiguration, PathJoinSubstitution,
                                          ThisLaunchFileDir)
        from launch_ros.actions import Node, PushRosNamespace


        def generate_launch_description():
            ns = LaunchConfiguration('ns')
            return LaunchDescription([
                DeclareLaunchArgument('ns', default_value='pond',
                                      description='Namespace of the pond'),
                DeclareLaunchArgument('follow', default_value='true'),
                DeclareLaunchArgument('inner', default_value='py'),
                GroupAction([
                    PushRosNamespace(ns),
                    Node(package='turtlesim', executable='turtlesim_node', name='sim',
                         parameters=[{'background_r': 200, 'background_b': 7}],
                         remappings=[('turtle1/pose', 'pose')]),
                ], scoped=True),
                IncludeLaunchDescription(
                    AnyLaunchDescriptionSource(PathJoinSubstitution(
                        [ThisLaunchFileDir(), ['mimic.launch.', LaunchConfiguration('inner')]])),
                    launch_arguments=[('src', ['/', ns, '/pose'])],
                    condition=IfCondition(LaunchConfiguration('follow'))),
                Node(package='demo_nodes_py', executable='listener', name='lonely',
                     condition=UnlessCondition(LaunchConfiguration('follow'))),
            ])
        ''',
    'mimic.launch.py': '''\
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument
        from launch.substitutions import LaunchConfiguration
        from launch_ros.actions import Node


        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('src'),
                Node(package='turtlesim', executable='mimic', name='follower',
                     remappings=[('/input/pose', LaunchConfiguration('src'))]),
            ])
        ''',
}

XML = {
    'pond.launch.xml': '''\
        <launch>
          <arg name="ns" default="pond" description="Namespace of the pond"/>
          <arg name="follow" default="true"/>
          <arg name="inner" default="xml"/>
          <group scoped="true">
            <push-ros-namespace namespace="$(var ns)"/>
            <node pkg="turtlesim" exec="turtlesim_node" name="sim">
              <param name="background_r" value="200"/>
              <param name="background_b" value="7" type="int"/>
              <remap from="turtle1/pose" to="pose"/>
            </node>
          </group>
          <include file="$(dirname)/mimic.launch.$(var inner)" if="$(var follow)">
            <arg name="src" value="/$(var ns)/pose"/>
          </include>
          <node pkg="demo_nodes_py" exec="listener" name="lonely" unless="$(var follow)"/>
        </launch>
        ''',
    'mimic.launch.xml': '''\
        <launch>
          <arg name="src"/>
          <node pkg="turtlesim" exec="mimic" name="follower">
            <remap from="/input/pose" to="$(var src)"/>
          </node>
        </launch>
        ''',
}

YAML = {
    'pond.launch.yaml': '''\
        launch:
        - arg:
            name: ns
            default: pond
            description: Namespace of the pond
        - arg:
            name: follow
            default: "true"
        - arg:
            name: inner
            default: yaml
        - group:
            scoped: true
            children:
            - push-ros-namespace:
                namespace: $(var ns)
            - node:
                pkg: turtlesim
                exec: turtlesim_node
                name: sim
                param:
                - name: background_r
                  value: 200
                - name: background_b
                  value: "7"
                  type: int
                remap:
                - from: turtle1/pose
                  to: pose
        - include:
            file: $(dirname)/mimic.launch.$(var inner)
            if: $(var follow)
            arg:
            - name: src
              value: /$(var ns)/pose
        - node:
            pkg: demo_nodes_py
            exec: listener
            name: lonely
            unless: $(var follow)
        ''',
    'mimic.launch.yaml': '''\
        launch:
        - arg:
            name: src
        - node:
            pkg: turtlesim
            exec: mimic
            name: follower
            remap:
            - from: /input/pose
              to: $(var src)
        ''',
}


@pytest.fixture(autouse=True)
def _clean():
    labkit.reset()
    yield
    labkit.reset()


@pytest.fixture
def pond(tmp_path):
    for files in (PY, XML, YAML):
        for name, text in files.items():
            (tmp_path / name).write_text(textwrap.dedent(text))
    return tmp_path


def _write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return str(path)


def _lines(result):
    """A launch that fails at once ends like a short command; otherwise it is a job."""
    if hasattr(result, 'output'):
        result.wait(1.0)
        return result.output
    return result.text().splitlines()


def _snapshot():
    """What the graph shows: nodes, the turtlesim's parameters, each node's pose topics,
    and the processes launch started, in order."""
    nodes = labkit.ros2('node list').stdout.split()
    sim = next(n for n in nodes if n.endswith('/sim'))
    params = [labkit.ros2(f'param get {sim} background_{c}').stdout for c in 'rb']
    topics = {n: [line.strip() for line in labkit.ros2(f'node info {n}').stdout.splitlines()
                  if 'pose' in line] for n in nodes}
    return nodes, params, topics


def _run(path, *arguments):
    job = labkit.ros2(f'launch {path} ' + ' '.join(arguments))
    labkit.sleep(1.0)
    started = [line.split(']: ')[0] + ']' for line in job.output
               if 'process started with pid' in line]
    return _snapshot() + (started,)


@pytest.mark.parametrize('arguments', [(), ('ns:=lake', 'follow:=false')])
def test_python_xml_and_yaml_start_the_same_graph(pond, arguments):
    seen = {}
    for ext in ('py', 'xml', 'yaml'):
        labkit.reset()
        seen[ext] = _run(pond / f'pond.launch.{ext}', *arguments)
    assert seen['xml'] == seen['py']
    assert seen['yaml'] == seen['py']
    nodes, params, topics, started = seen['py']
    assert params == ['Integer value is: 200\n', 'Integer value is: 7\n']
    if arguments:
        assert nodes == ['/lake/sim', '/lonely']
        assert topics['/lake/sim'] == ['/lake/pose: turtlesim/msg/Pose']
        assert started == ['[INFO] [turtlesim_node-1]', '[INFO] [listener-2]']
    else:
        assert nodes == ['/follower', '/pond/sim']
        assert topics['/pond/sim'] == ['/pond/pose: turtlesim/msg/Pose']
        assert topics['/follower'] == ['/pond/pose: turtlesim/msg/Pose']    # the remap
        assert started == ['[INFO] [turtlesim_node-1]', '[INFO] [mimic-2]']


@pytest.mark.parametrize('top, inner', [('py', 'xml'), ('py', 'yaml'), ('xml', 'py'),
                                        ('xml', 'yaml'), ('yaml', 'py'), ('yaml', 'xml')])
def test_each_front_end_includes_the_others(pond, top, inner):
    nodes, _, topics, _ = _run(pond / f'pond.launch.{top}', f'inner:={inner}')
    assert nodes == ['/follower', '/pond/sim']
    assert topics['/follower'] == ['/pond/pose: turtlesim/msg/Pose']


def test_show_args_is_the_same_for_the_three(pond):
    shown = {ext: labkit.ros2(f'launch {pond}/pond.launch.{ext} --show-args').stdout
             for ext in ('py', 'xml', 'yaml')}
    assert shown['xml'].replace("'xml'", "'py'") == shown['py']
    assert shown['yaml'].replace("'yaml'", "'py'") == shown['py']
    assert shown['xml'] == (
        "Arguments (pass arguments as '<name>:=<value>'):\n\n"
        "    'ns':\n        Namespace of the pond\n        (default: 'pond')\n\n"
        "    'follow':\n        no description given\n        (default: 'true')\n\n"
        "    'inner':\n        no description given\n        (default: 'xml')\n")


SUBSTITUTIONS = '''\
    <launch>
      <arg name="who" default="turtle"/>
      <set_env name="LABKIT_FE_COLOR" value="green"/>
      <log message="var=$(var who) $(var nobody 'a default')"/>
      <log message="env=$(env LABKIT_FE_COLOR) $(env LABKIT_FE_UNSET 'no such')"/>
      <log message="eval=$(eval '6 * 7')"/>
      <log message="anon=$(anon talker) $(anon talker)"/>
      <log message="dirname=$(dirname)"/>
      <log message="filename=$(filename)"/>
      <log message="share=$(find-pkg-share turtlesim)"/>
      <log message="prefix=$(find-pkg-prefix turtlesim)"/>
      <log message="exec=$(exec-in-pkg turtlesim_node turtlesim)"/>
      <log message="bool=$(not $(eval '2 > 1')) $(and true $(var flag true))"/>
      <log message="or=$(or $(var flag) true)"/>
      <log message="escaped=\\$(var who)"/>
    </launch>
    '''


def _as_yaml(xml_text):
    """The same launch file in YAML (every tag here is a flat one)."""
    root = ET.fromstring(textwrap.dedent(xml_text))
    lines = ['launch:']
    for child in root:
        lines.append(f'- {child.tag}:')
        for key, value in child.attrib.items():
            lines.append(f'    {key}: "{value}"'.replace('\\$', '\\\\$'))
    return '\n'.join(lines) + '\n'


@pytest.mark.parametrize('ext', ['xml', 'yaml'])
def test_every_substitution(tmp_path, ext):
    from labkit.ament.index import get_package_prefix, get_package_share_directory
    text = SUBSTITUTIONS if ext == 'xml' else _as_yaml(SUBSTITUTIONS)
    path = _write(tmp_path, f'subs.launch.{ext}', text)
    job = labkit.ros2(f'launch {path} who:=leo flag:=false')
    said = dict(line.split(': ', 1)[1].split('=', 1) for line in _lines(job)
                if line.startswith('[INFO] [launch.user]: '))
    os.environ.pop('LABKIT_FE_COLOR', None)
    anon = said.pop('anon').split()
    assert anon[0] == anon[1] and anon[0].startswith('talker_') and anon[0] != 'talker_'
    assert said == {
        'var': 'leo a default',
        'env': 'green no such',
        'eval': '42',
        'dirname': str(tmp_path),
        'filename': path,
        'share': get_package_share_directory('turtlesim'),
        'prefix': get_package_prefix('turtlesim'),
        'exec': '/opt/ros/humble/lib/turtlesim/turtlesim_node',
        'bool': 'false false',
        'or': 'true',
        'escaped': '$(var who)',
    }


def test_list_attributes_and_typed_values():
    def attr(text, name, **kw):
        return frontend.XmlEntity(ET.fromstring(text)).get_attr(name, **kw)
    assert attr('<p value="1;2;3" value-sep=";"/>', 'value', data_type=None) == [1, 2, 3]
    assert attr('<p value="a, b" value-sep=","/>', 'value',
                data_type=frontend.list_of(str)) == ['a', ' b']
    assert attr('<p value="[1.5, 2.0]"/>', 'value', data_type=None) == [1.5, 2.0]
    assert attr('<p value="true"/>', 'value', data_type=None) is True
    assert attr('<p value="007"/>', 'value', data_type=str) == '007'
    assert attr('<g scoped="false"/>', 'scoped', data_type=bool) is False
    with pytest.raises(TypeError, match="Attribute 'value' of Entity 'p' expected to be of "
                                        "type 'None'.'{a: 1}' can not be converted"):
        attr('<p value="{a: 1}"/>', 'value', data_type=None)
    yaml_entity = frontend.YamlEntity({'period': 5}, 'timer')
    with pytest.raises(TypeError, match="Attribute 'period' of Entity 'timer' expected to be "
                                        "of type '<class 'float'>', got '<class 'int'>'"):
        yaml_entity.get_attr('period', data_type=float)


def test_typed_and_listed_parameters_reach_the_node(tmp_path):
    path = _write(tmp_path, 'typed.launch.xml', '''\
        <launch>
          <node pkg="turtlesim" exec="turtlesim_node" name="typed">
            <param name="background_r" value="$(eval '40 + 2')"/>
            <param name="background_g" value="9" type="int"/>
            <param from="$(dirname)/colors.yaml"/>
          </node>
        </launch>
        ''')
    _write(tmp_path, 'colors.yaml', '''\
        /**:
          ros__parameters:
            background_b: 11
        ''')
    labkit.ros2(f'launch {path}')
    labkit.sleep(0.5)
    got = [labkit.ros2(f'param get /typed background_{c}').stdout for c in 'rgb']
    assert got == ['Integer value is: 42\n', 'Integer value is: 9\n',
                   'Integer value is: 11\n']


XML_ERRORS = [
    ('<launch>\n  <node pkg="turtlesim" exec="turtlesim_node" nmae="x"/>\n</launch>\n',
     [" - ValueError: Unexpected attribute(s) found in `node`: {'nmae'}"]),
    ('<launch>\n  <node pkg="turtlesim" exec="turtlesim_node"><frob/></node>\n</launch>\n',
     [" - ValueError: Unexpected nested tag(s) found in `node`: {'frob'}"]),
    ('<launch>\n  <node pkg="turtlesim" exec="mimic">\n'
     '    <remap from="a" to="b" too="c"/>\n  </node>\n</launch>\n',
     [" - ValueError: Unexpected attribute(s) found in `remap`: {'too'}"]),
    ('<launch>\n  <node pkg="turtlesim" name="x"/>\n</launch>\n',
     [" - AttributeError: Attribute 'exec' of type '<class 'str'>' not found in Entity "
      "'node'"]),
    ('<launch>\n  <include>\n    <arg name="a" value="b"/>\n  </include>\n</launch>\n',
     [" - AttributeError: Attribute 'file' of type '<class 'str'>' not found in Entity "
      "'include'"]),
    ('<launch>\n  <log message="$(exec-in-pkg mimic)"/>\n</launch>\n',
     [' - AttributeError: exec-in-package substitution expects 2 arguments']),
    ('<launch>\n  <log message="$(dirname x)"/>\n</launch>\n',
     [" - TypeError: dirname substitution doesn't expect arguments"]),
    ('<launch>\n  <frob/>\n</launch>\n',
     [' - RuntimeError: Unrecognized entity of the type: frob']),
    ('<launch>\n  <log message="$(nope x)"/>\n</launch>\n',
     [' - RuntimeError: Unknown substitution: nope']),
    ('<launch>\n  <node pkg="turtlesim" exec="turtlesim_node">\n'
     '    <param name="background_r" value="1" type="integer"/>\n  </node>\n</launch>\n',
     [" - ValueError: Got invalid type identifier 'integer'"]),
    ('<launch>\n  <node pkg="turtlesim" exec="turtlesim_node" if="a" unless="b"/>\n'
     '</launch>\n', [" - RuntimeError: if and unless conditions can't be used simultaneously"]),
    # not XML at all: launch's frontend tried every parser, then launch tried Python
    ('<launch>\n  <node pkg="turtlesim" exec="turtlesim_node">\n</launch>\n',
     [' - InvalidFrontendLaunchFileError: Caught multiple exceptions when trying to load '
      'file of format [xml]:',
      ' - ParseError: mismatched tag: line 3, column 2',
      ' - RuntimeError: Expected only one root']),
]


YAML_ERRORS = [
    ('launch:\n- node:\n    pkg: turtlesim\n    exec: turtlesim_node\n    nmae: x\n',
     [" - ValueError: Unexpected key(s) found in `node`: {'nmae'}"]),
    ('launch:\n- node:\n    pkg: turtlesim\n',
     [" - AttributeError: Can not find attribute 'exec' in Entity 'node'"]),
    ('launch:\n- timer:\n    period: 2\n    children:\n    - log: {message: hi}\n',
     [" - TypeError: Attribute 'period' of Entity 'timer' expected to be of type "
      "'<class 'float'>', got '<class 'int'>'"]),
    ('launch:\n- let: {name: x, value: 150}\n',
     [" - TypeError: Attribute 'value' of Entity 'let' expected to be of type "
      "'<class 'str'>', got '<class 'int'>'"]),
    ('launch:\n- frob: {}\n', [' - RuntimeError: Unrecognized entity of the type: frob']),
]


ERRORS = [('xml', t, e) for t, e in XML_ERRORS] + [('yaml', t, e) for t, e in YAML_ERRORS]


@pytest.mark.parametrize('ext, text, errors', ERRORS)
def test_bad_files_in_launchs_words(tmp_path, ext, text, errors):
    path = _write(tmp_path, f'broken.launch.{ext}', text)
    lines = _lines(labkit.ros2(f'launch {path}'))
    start = lines.index('[ERROR] [launch]: Caught exception in launch (see debug for '
                        'traceback): Caught multiple exceptions when trying to load file of '
                        f'format [{ext}]:')
    assert lines[start + 1:start + 1 + len(errors)] == errors
    assert lines[start + 1 + len(errors)].startswith(' - SyntaxError: ')    # tried as Python
    assert not any('Traceback' in line or 'File "' in line for line in lines)


def test_an_empty_or_unreadable_yaml_file(tmp_path):
    """launch tries every front-end, then Python: an empty file IS Python, without
    generate_launch_description()."""
    path = _write(tmp_path, 'empty.launch.yaml', '')
    lines = _lines(labkit.ros2(f'launch {path}'))
    assert lines[-4:] == [
        ' - InvalidFrontendLaunchFileError: Caught multiple exceptions when trying to load '
        'file of format [yaml]:',
        " - TypeError: object of type 'NoneType' has no len()",
        ' - ParseError: no element found: line 1, column 0',
        f" - InvalidPythonLaunchFileError: launch file at '{path}' does not contain the "
        "required function 'generate_launch_description()'"]
    path = _write(tmp_path, 'bad.launch.yaml', 'launch:\n- node: {pkg: turtlesim\n')
    lines = _lines(labkit.ros2(f'launch {path}'))
    assert ' - ParserError: while parsing a flow mapping' in lines
    assert ' - ParseError: syntax error: line 1, column 0' in lines


def test_including_a_missing_file(tmp_path):
    path = _write(tmp_path, 'top.launch.xml', '<launch><include file="$(dirname)/no.xml"/>'
                                              '</launch>')
    missing = f" - FileNotFoundError: [Errno 2] No such file or directory: '{tmp_path}/no.xml'"
    assert _lines(labkit.ros2(f'launch {path}'))[-3:] == [
        '[ERROR] [launch]: Caught exception in launch (see debug for traceback): Caught '
        'multiple exceptions when trying to load file of format [xml]:', missing, missing]


def test_a_file_of_no_launch_format(tmp_path):
    path = _write(tmp_path, 'notes.txt', 'just some words: here\n')
    lines = _lines(labkit.ros2(f'launch {path}'))
    assert lines[-1] == ('[ERROR] [launch]: Caught exception in launch (see debug for '
                         'traceback): The launch file may have a syntax error, or its format '
                         'is unknown')


def test_reset_forgets_launch_configurations_but_the_kept_ones(tmp_path):
    path = _write(tmp_path, 'reset.launch.yaml', '''\
        launch:
        - let: {name: a, value: one}
        - let: {name: b, value: two}
        - reset:
            keep:
            - {name: c, value: $(var a)}
        - log: {message: "a=$(var a gone) b=$(var b gone) c=$(var c)"}
        - reset: {}
        - log: {message: "c=$(var c gone)"}
        ''')
    lines = _lines(labkit.ros2(f'launch {path}'))
    assert '[INFO] [launch.user]: a=gone b=gone c=one' in lines
    assert '[INFO] [launch.user]: c=gone' in lines


def test_executable_and_node_take_every_process_attribute(tmp_path):
    """`<node>` has all of `<executable>`'s attributes but `cmd` (launch_ros's Node.parse);
    none of them is 'unexpected'."""
    path = _write(tmp_path, 'process.launch.xml', '''\
        <launch>
          <node pkg="turtlesim" exec="turtlesim_node" name="full" output="screen"
                respawn="false" respawn_delay="1.0" cwd="/" launch-prefix="" shell="false"
                exec_name="pondsim" ros_args="--log-level warn">
            <env name="A" value="1"/>
          </node>
          <reset_env/>
        </launch>
        ''')
    job = labkit.ros2(f'launch {path}')
    labkit.sleep(0.5)
    assert labkit.ros2('node list').stdout.split() == ['/full']
    assert any(line.startswith('[INFO] [pondsim-1]: process started with pid [')
               for line in job.output)
    bad = _write(tmp_path, 'delay.launch.xml',
                 '<launch><node pkg="turtlesim" exec="turtlesim_node" respawn_delay="-1"/>'
                 '</launch>')
    assert (' - ValueError: Attribute respawn_delay of Entity node expected to be a '
            'non-negative value but got `-1.0`') in _lines(labkit.ros2(f'launch {bad}'))


# ------------------------------------------------------------------ from a package

def test_launch_a_package_xml_file_with_arguments_and_show_args(ws):
    """`ros2 launch <package> pond.launch.xml ns:=lake` after colcon build, as the
    official tutorials do it; the YAML file of the same package too."""
    from facer_ws import python_package
    from labkit.ament import colcon, source
    root = python_package(str(ws / 'src'), 'pond_bringup', [],
                          deps=[('exec_depend', 'turtlesim')])
    setup = os.path.join(root, 'setup.py')
    with open(setup, encoding='utf-8') as f:
        text = f.read()
    with open(setup, 'w', encoding='utf-8') as f:
        f.write(text.replace("glob('launch/*.launch.py')", "glob('launch/*.launch.*')"))
    for files in (XML, YAML):
        for name, body in files.items():
            os.makedirs(os.path.join(root, 'launch'), exist_ok=True)
            with open(os.path.join(root, 'launch', name), 'w', encoding='utf-8') as f:
                f.write(textwrap.dedent(body))
    assert colcon.run_command('build').returncode == 0
    assert source.run('install/setup.bash') == 0
    shown = labkit.ros2('launch pond_bringup pond.launch.xml --show-args').stdout
    assert "    'ns':\n        Namespace of the pond\n        (default: 'pond')\n" in shown
    shown = labkit.ros2('launch pond_bringup pond.launch.yaml --show-args').stdout
    assert "    'inner':\n        no description given\n        (default: 'yaml')\n" in shown
    job = labkit.ros2('launch pond_bringup pond.launch.xml ns:=lake')
    labkit.sleep(1.0)
    assert labkit.ros2('node list').stdout.split() == ['/follower', '/lake/sim']
    assert '/lake/pose: turtlesim/msg/Pose' in labkit.ros2('node info /follower').stdout


# ------------------------------------------------------------------ the tutorial's shape

COLORS = {
    'yaml': '''\
        launch:
        - arg: {name: pond, default: 'pond1'}
        - arg: {name: really, default: 'False'}
        - arg: {name: red, default: '90'}
        - node: {pkg: turtlesim, exec: turtlesim_node, name: sim, namespace: '$(var pond)'}
        - executable:
            cmd: 'ros2 service call $(var pond)/spawn turtlesim/srv/Spawn "{x: 3, y: 4}"'
        - executable:
            cmd: 'ros2 param set $(var pond)/sim background_r 10'
        - timer:
            period: 2.0
            children:
            - executable:
                cmd: 'ros2 param set $(var pond)/sim background_r $(var red)'
                if: '$(eval "$(var red) == 90 and $(var really)")'
        ''',
    'xml': '''\
        <launch>
          <arg name="pond" default="pond1"/>
          <arg name="really" default="False"/>
          <arg name="red" default="90"/>
          <node pkg="turtlesim" exec="turtlesim_node" name="sim" namespace="$(var pond)"/>
          <executable
              cmd="ros2 service call $(var pond)/spawn turtlesim/srv/Spawn '{x: 3, y: 4}'"/>
          <executable cmd="ros2 param set $(var pond)/sim background_r 10"/>
          <timer period="2.0">
            <executable cmd="ros2 param set $(var pond)/sim background_r $(var red)"
                        if="$(eval '$(var red) == 90 and $(var really)')"/>
          </timer>
        </launch>
        ''',
}

MAIN = {
    'yaml': '''\
        launch:
        - let: {name: r, value: '90'}
        - include:
            file: '$(dirname)/colors.launch.yaml'
            arg:
            - {name: pond, value: pond2}
            - {name: really, value: 'True'}
            - {name: red, value: '$(var r)'}
        ''',
    'xml': '''\
        <launch>
          <let name="r" value="90"/>
          <include file="$(dirname)/colors.launch.xml">
            <arg name="pond" value="pond2"/>
            <arg name="really" value="True"/>
            <arg name="red" value="$(var r)"/>
          </include>
        </launch>
        ''',
}


@pytest.mark.parametrize('ext', ['xml', 'yaml'])
def test_executables_timer_and_eval_condition_as_in_the_substitutions_tutorial(tmp_path, ext):
    """The shape of the official "Using substitutions" tutorial: a main file passes `let`
    values to an include; `executable` runs ros2 commands; a timer's `if` uses `$(eval)`."""
    _write(tmp_path, f'colors.launch.{ext}', COLORS[ext])
    main = _write(tmp_path, f'main.launch.{ext}', MAIN[ext])
    job = labkit.ros2(f'launch {main}')
    labkit.sleep(1.0)
    assert labkit.ros2('param get /pond2/sim background_r').stdout == 'Integer value is: 10\n'
    assert '/pond2/turtle2/pose' in labkit.ros2('topic list').stdout.split()
    labkit.sleep(2.0)
    assert labkit.ros2('param get /pond2/sim background_r').stdout == 'Integer value is: 90\n'
    assert '[INFO] [ros2-4]: process has finished cleanly' in ' '.join(job.output)
    labkit.reset()
    colors = tmp_path / f'colors.launch.{ext}'
    labkit.ros2(f'launch {colors}')                     # really defaults to False: no timer
    labkit.sleep(3.0)
    assert labkit.ros2('param get /pond1/sim background_r').stdout == 'Integer value is: 10\n'


def test_xml_source_reads_xml_only(pond):
    """XMLLaunchDescriptionSource is launch_xml's parser alone: a YAML file is its
    ParseError (AnyLaunchDescriptionSource would have tried YAML too)."""
    path = _write(pond, 'wrong.launch.py', f'''\
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription
        from launch_xml.launch_description_sources import XMLLaunchDescriptionSource


        def generate_launch_description():
            return LaunchDescription([IncludeLaunchDescription(
                XMLLaunchDescriptionSource({str(pond / 'mimic.launch.yaml')!r}),
                launch_arguments=[('src', '/x')])])
        ''')
    assert _lines(labkit.ros2(f'launch {path}'))[-1] == (
        '[ERROR] [launch]: Caught exception in launch (see debug for traceback): '
        'syntax error: line 1, column 0')
