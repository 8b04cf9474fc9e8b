"""Chapter 21's XML and YAML launch files, taken from the notebook as it writes them:
the mimic system in three formats starts one graph; pond.launch.xml does what
pond.launch.py does; ponds.launch.xml's group, param file and remaps; the misspelt
attribute answers in launch's words."""
import pytest

import labkit
from test_ch21_files import lab, launch, nodes, param, started, written_files  # noqa: F401


def _graph(job):
    """Processes started (in order), nodes, and what /mimic subscribes and publishes."""
    labkit.sleep(1.0)
    mimic = [line.strip() for line in labkit.ros2('node info /mimic').stdout.splitlines()
             if 'turtle1' in line]
    return started(job.output), nodes(), mimic


def test_mimic_system_in_three_formats_is_one_graph(tmp_path, monkeypatch):
    files = written_files()
    monkeypatch.chdir(tmp_path)
    seen = {}
    for name in ('mimic_launch.py', 'mimic.launch.xml', 'mimic.launch.yaml'):
        (tmp_path / name).write_text(files[name], encoding='utf-8')
        job = launch(f'launch {name}')
        seen[name] = _graph(job)
        job.stop()
        assert nodes() == []
        labkit.reset()
    assert seen['mimic_launch.py'] == (
        ['turtlesim_node-1', 'turtlesim_node-2', 'mimic-3'],
        ['/mimic', '/turtlesim1/sim', '/turtlesim2/sim'],
        ['/turtlesim1/turtle1/pose: turtlesim/msg/Pose',
         '/turtlesim2/turtle1/cmd_vel: geometry_msgs/msg/Twist'])
    assert seen['mimic.launch.xml'] == seen['mimic_launch.py']
    assert seen['mimic.launch.yaml'] == seen['mimic_launch.py']


def test_pond_xml_shows_the_same_arguments_as_pond_py(lab):
    python = labkit.ros2('launch launch_lab pond.launch.py --show-args').stdout
    xml = labkit.ros2('launch launch_lab pond.launch.xml --show-args').stdout
    assert "    'use_red':\n        no description given\n        (default: 'False')\n" in xml
    assert xml == python


@pytest.mark.parametrize('arguments, red', [
    ('pond:=turtlesim4 use_red:=True red:=60', 60),
    ('pond:=turtlesim4', 120),                          # use_red defaults to False
    ('pond:=turtlesim4 use_red:=True red:=300', 120),   # not a colour: the timer does nothing
])
def test_pond_xml_spawns_and_colours_like_pond_py(lab, arguments, red):
    job = launch(f'launch launch_lab pond.launch.xml {arguments}')
    labkit.sleep(1.0)
    assert nodes() == ['/turtlesim4/sim']
    assert '/turtlesim4/turtle2/pose' in labkit.ros2('topic list').stdout.split()
    assert param('/turtlesim4/sim', 'background_r') == 'Integer value is: 120'
    labkit.sleep(2.0)                                   # the timer's 2 s are over
    assert param('/turtlesim4/sim', 'background_r') == f'Integer value is: {red}'
    assert started(job.output)[:3] == ['turtlesim_node-1', 'ros2-2', 'ros2-3']
    assert ('ros2-4' in started(job.output)) == (red == 60)
    job.stop()


def test_ponds_xml_group_param_file_and_remaps(lab, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / 'ponds.launch.xml').write_text(written_files()['ponds.launch.xml'], encoding='utf-8')
    job = launch('launch ponds.launch.xml')
    labkit.sleep(1.0)
    assert nodes() == ['/mimic', '/sim', '/turtlesim2/sim']
    assert param('/turtlesim2/sim', 'background_g') == 'Integer value is: 110'
    assert param('/sim', 'background_g') == 'Integer value is: 86'      # outside the group
    mimic = labkit.ros2('node info /mimic').stdout
    assert '/turtle1/pose: turtlesim/msg/Pose' in mimic
    assert '/turtlesim2/turtle1/cmd_vel: geometry_msgs/msg/Twist' in mimic
    job.stop()


def test_a_misspelt_attribute_is_named_and_nothing_starts(lab, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    text = written_files()['ponds.launch.xml'].replace('name="mimic"', 'nmae="mimic"')
    (tmp_path / 'typo.launch.xml').write_text(text, encoding='utf-8')
    result = labkit.ros2('launch typo.launch.xml')
    lines = result.text().splitlines()
    assert lines[-3:] == [
        '[ERROR] [launch]: Caught exception in launch (see debug for traceback): Caught '
        'multiple exceptions when trying to load file of format [xml]:',
        " - ValueError: Unexpected attribute(s) found in `node`: {'nmae'}",
        ' - SyntaxError: invalid syntax (typo.launch.xml, line 1)']
    assert nodes() == []
    assert not any('Traceback' in line or 'File "' in line for line in lines)
