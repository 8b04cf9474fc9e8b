"""`ros2 launch x.launch.xml` / `x.launch.yaml` (issue 13): the XML and YAML front-ends
with launch's and launch_ros's real tags, attributes and `$(...)` substitutions, giving
the same graph as the Python front-end; errors in launch's words."""
import os
import textwrap

import pytest

import labkit
from labkit.launch import frontend

XML = '''\
<launch>
  <arg name="ns" default="sim" description="Namespace of the turtles"/>
  <arg name="speed" default="fast">
    <choice value="fast"/>
    <choice value="slow"/>
  </arg>
  <let name="color" value="150"/>
  <log message="starting in $(var ns)"/>
  <group>
    <push-ros-namespace namespace="$(var ns)"/>
    <node pkg="turtlesim" exec="turtlesim_node" name="sim">
      <param name="background_r" value="$(var color)"/>
      <param name="background_g" value="20"/>
      <param name="background_b" value="$(eval '2 * 60')"/>
    </node>
  </group>
  <node pkg="turtlesim" exec="mimic" name="mimic" if="$(eval '\\'$(var speed)\\' == \\'fast\\'')">
    <remap from="/input/pose" to="/$(var ns)/turtle1/pose"/>
    <remap from="/output/cmd_vel" to="/mimic/turtle1/cmd_vel"/>
  </node>
  <node pkg="demo_nodes_py" exec="talker" unless="true"/>
</launch>
'''

YAML = '''\
launch:
- arg:
    name: ns
    default: sim
    description: Namespace of the turtles
- arg:
    name: speed
    default: fast
    choice:
    - value: fast
    - value: slow
- let:
    name: color
    value: "150"
- log:
    message: starting in $(var ns)
- group:
    children:
    - push-ros-namespace:
        namespace: $(var ns)
    - node:
        pkg: turtlesim
        exec: turtlesim_node
        name: sim
        param:
        - name: background_r
          value: $(var color)
        - name: background_g
          value: 20
        - name: background_b
          value: $(eval '2 * 60')
- node:
    pkg: turtlesim
    exec: mimic
    name: mimic
    if: $(eval '\\'$(var speed)\\' == \\'fast\\'')
    remap:
    - from: /input/pose
      to: /$(var ns)/turtle1/pose
    - from: /output/cmd_vel
      to: /mimic/turtle1/cmd_vel
- node:
    pkg: demo_nodes_py
    exec: talker
    unless: "true"
'''


@pytest.fixture(autouse=True)
def _clean():
    labkit.reset()
    yield
    labkit.reset()


def _write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return str(path)


def _graph():
    return (labkit.ros2('node list').stdout.split(),
            [labkit.ros2(f'param get /foo/sim background_{c}').stdout for c in 'rgb'],
            labkit.ros2('node info /mimic').stdout)


@pytest.mark.parametrize('name, text', [('turtles.launch.xml', XML),
                                        ('turtles.launch.yaml', YAML)])
def test_both_front_ends_start_the_same_graph(tmp_path, name, text):
    path = _write(tmp_path, name, text)
    job = labkit.ros2(f'launch {path} ns:=foo')
    labkit.sleep(1.0)
    nodes, params, mimic = _graph()
    assert nodes == ['/foo/sim', '/mimic']          # talker: unless="true"
    assert params == ['Integer value is: 150\n', 'Integer value is: 20\n',
                      'Integer value is: 120\n']
    assert '    /foo/turtle1/pose: turtlesim/msg/Pose\n' in mimic
    assert '    /mimic/turtle1/cmd_vel: geometry_msgs/msg/Twist\n' in mimic
    assert '[INFO] [launch.user]: starting in foo' in job.output
    shown = labkit.ros2(f'launch {path} --show-args').stdout
    assert "    'ns':\n        Namespace of the turtles\n        (default: 'sim')\n" in shown
    assert "    'speed':\n        One of: ['fast', 'slow']\n        (default: 'fast')\n" in shown


def test_conditions_and_choices_take_arguments(tmp_path):
    path = _write(tmp_path, 'turtles.launch.xml', XML)
    labkit.ros2(f'launch {path} speed:=slow')
    labkit.sleep(0.5)
    assert labkit.ros2('node list').stdout.split() == ['/sim/sim']
    labkit.reset()
    job = labkit.ros2(f'launch {path} speed:=medium')
    lines = job.output if hasattr(job, 'output') else job.text().splitlines()
    assert ('[ERROR] [launch]: Argument "speed" provided value "medium" is not valid. '
            "Valid options are: ['fast', 'slow']") in lines


def test_include_between_formats_with_arguments_and_scoped_groups(tmp_path):
    _write(tmp_path, 'inner.launch.yaml', '''\
        launch:
        - arg: {name: who}
        - let: {name: leaked, value: "yes"}
        - node:
            pkg: turtlesim
            exec: turtlesim_node
            name: $(var who)
        ''')
    outer = _write(tmp_path, 'outer.launch.xml', '''\
        <launch>
          <group scoped="true">
            <include file="$(dirname)/inner.launch.yaml">
              <arg name="who" value="alpha"/>
            </include>
          </group>
          <log message="leaked=$(var leaked none)"/>
          <set_env name="LABKIT_FRONTEND_TEST" value="42"/>
          <log message="env=$(env LABKIT_FRONTEND_TEST)"/>
          <set_parameter name="background_b" value="7"/>
          <set_remap from="/turtle1/pose" to="/beta_pose"/>
          <node pkg="turtlesim" exec="turtlesim_node" name="beta"/>
        </launch>
        ''')
    python = _write(tmp_path, 'top.launch.py', f'''\
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription
        from launch.launch_description_sources import AnyLaunchDescriptionSource


        def generate_launch_description():
            return LaunchDescription([
                IncludeLaunchDescription(AnyLaunchDescriptionSource({outer!r})),
            ])
        ''')
    job = labkit.ros2(f'launch {python}')
    labkit.sleep(0.5)
    assert labkit.ros2('node list').stdout.split() == ['/alpha', '/beta']
    assert '[INFO] [launch.user]: leaked=none' in job.output      # the group's scope
    assert '[INFO] [launch.user]: env=42' in job.output
    assert labkit.ros2('param get /beta background_b').stdout == 'Integer value is: 7\n'
    assert '    /beta_pose: turtlesim/msg/Pose\n' in labkit.ros2('node info /beta').stdout
    os.environ.pop('LABKIT_FRONTEND_TEST', None)   # launch runs in-process: its environment


def test_timer_executable_and_typed_params(tmp_path):
    path = _write(tmp_path, 'more.launch.xml', '''\
        <launch>
          <timer period="1.5">
            <log message="later"/>
          </timer>
          <executable cmd="ros2 topic list" name="lister" output="screen"/>
          <node pkg="turtlesim" exec="turtlesim_node" name="typed">
            <param name="background_r" value="9" type="int"/>
            <param name="qos_overrides">
              <param name="nothing" value="x"/>
            </param>
          </node>
        </launch>
        ''')
    job = labkit.ros2(f'launch {path}')
    labkit.sleep(2.0)
    assert '[INFO] [launch.user]: later' in job.output
    assert any(line.startswith('[INFO] [lister-1]: process started') for line in job.output)
    assert labkit.ros2('param get /typed background_r').stdout == 'Integer value is: 9\n'


@pytest.mark.parametrize('text, error', [
    ('<launch>\n  <node pkg="turtlesim" exec="turtlesim_node">\n</launch>\n',
     ' - ParseError: mismatched tag: line 3, column 2'),
    ('<launch>\n  <frob/>\n</launch>\n', ' - RuntimeError: Unrecognized entity of the type: frob'),
    ('<launch>\n  <log message="$(nope x)"/>\n</launch>\n',
     ' - RuntimeError: Unknown substitution: nope'),
    ('<notlaunch/>\n', " - RuntimeError: Expected 'launch' as root tag"),
])
def test_errors_are_launchs(tmp_path, text, error):
    path = _write(tmp_path, 'broken.launch.xml', text)
    r = labkit.ros2(f'launch {path}')
    assert r.returncode == 1
    lines = r.text().splitlines()
    assert ('[ERROR] [launch]: Caught exception in launch (see debug for traceback): '
            'Caught multiple exceptions when trying to load file of format [xml]:') in lines
    assert error in lines
    assert lines[-1].startswith(' - SyntaxError: ')     # launch also tried it as Python
    assert 'Traceback' not in r.text() and 'File "' not in r.text()


def test_substitution_grammar():
    from labkit.launch.launch_context import LaunchContext
    from labkit.launch.utilities import perform
    context = LaunchContext()
    context.launch_configurations.update({'a': 'x y', 'b': '2'})
    cases = {
        'plain text': 'plain text',
        '$(var a)-$(var b)': 'x y-2',
        '$(var missing dflt)': 'dflt',
        "$(var missing 'with space')": 'with space',
        '$(eval "$(var b) * 3")': '6',
        '$(not true)': 'false',
        '$(and true $(not false))': 'true',
        r'cost \$(var a)': 'cost $(var a)',
        '$(env LABKIT_NOT_SET_ANYWHERE fallback)': 'fallback',
    }
    for text, expected in cases.items():
        assert perform(context, frontend.parse_substitution(text)) == expected, text
    with pytest.raises(TypeError, match='var substitution expects 1 or 2 arguments'):
        frontend.parse_substitution('$(var)')


def test_cmdline_splitting_keeps_substitutions_together():
    from labkit.launch.launch_context import LaunchContext
    from labkit.launch.utilities import perform
    context = LaunchContext()
    context.launch_configurations['d'] = '/opt/x'
    args = frontend._cmdline('ros2 run $(var d)/bin "quoted arg" last')
    assert [perform(context, a) for a in args] == ['ros2', 'run', '/opt/x/bin', 'quoted arg',
                                                   'last']


def test_frontend_source_class_includes_a_yaml_file(tmp_path):
    _write(tmp_path, 'one.launch.yaml', '''\
        launch:
        - node: {pkg: turtlesim, exec: turtlesim_node, name: solo}
        ''')
    _write(tmp_path, 'two.launch.xml', '''\
        <launch><node pkg="turtlesim" exec="turtlesim_node" name="duo"/></launch>
        ''')
    python = _write(tmp_path, 'top.launch.py', f'''\
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription
        from launch.launch_description_sources import FrontendLaunchDescriptionSource
        from launch_xml.launch_description_sources import XMLLaunchDescriptionSource
        from launch_yaml.launch_description_sources import YAMLLaunchDescriptionSource


        def generate_launch_description():
            return LaunchDescription([
                IncludeLaunchDescription(
                    FrontendLaunchDescriptionSource({str(tmp_path / 'one.launch.yaml')!r})),
                IncludeLaunchDescription(
                    XMLLaunchDescriptionSource({str(tmp_path / 'two.launch.xml')!r})),
                IncludeLaunchDescription(
                    YAMLLaunchDescriptionSource({str(tmp_path / 'one.launch.yaml')!r}),
                    launch_arguments=[]),
            ])
        ''')
    labkit.ros2(f'launch {python}')
    labkit.sleep(0.3)
    assert labkit.ros2('node list').stdout.split() == ['/duo', '/solo', '/solo']
