"""Every path labkit prints inside the sandbox (/root/...) works when typed back.

In a chapter's sandbox `~` is a folder next to the notebook that labkit shows as
/root (as a terminal in the container would). A learner copying such a path from
an output (`ros2 pkg prefix`, `pwd`, `ros2 bag record`'s folder) into a command must
reach the same file, as on the Ubuntu machine the text reads like.
"""
import os

import pytest

import labkit
from labkit.ament import files


@pytest.fixture
def sandbox(tmp_path):
    previous = os.getcwd()
    files.use_home(str(tmp_path / 'home'))
    try:
        yield tmp_path / 'home'
    finally:
        files.leave_home()
        os.chdir(previous)
        labkit.reset()


def test_expand_maps_the_shown_home_back(sandbox):
    assert files.expand('/root') == str(sandbox)
    assert files.expand('/root/ros2_ws/src') == os.path.join(str(sandbox), 'ros2_ws', 'src')
    # round trip: display() of the real path is what was typed
    assert files.display(files.expand('/root/a/b.txt')) == '/root/a/b.txt'
    # other absolute paths and look-alikes stay what they are
    assert files.expand('/rootfs/x') == '/rootfs/x'
    assert files.expand('/opt/ros/humble') == '/opt/ros/humble'
    assert files.expand_arg('source:=/root/x.avi') == 'source:=/root/x.avi'


def test_expand_outside_a_sandbox_leaves_root_alone():
    assert files.expand('/root/x') == '/root/x'
    assert files.expand_arg('/root/x') == '/root/x'


def test_shell_helpers_accept_the_shown_path(sandbox, capsys):
    files.mkdir('~/ros2_ws/src')
    files.write_text(files.expand('~/ros2_ws/src/note.txt'), 'hello\n')
    files.cd('/root/ros2_ws')
    files.pwd()
    files.cat('/root/ros2_ws/src/note.txt')
    assert capsys.readouterr().out == '/root/ros2_ws\nhello\n'


def test_ros2_launch_by_the_full_path_that_was_printed(sandbox):
    files.mkdir('~/ros2_ws/launch')
    files.write_text(files.expand('~/ros2_ws/launch/empty_launch.py'),
                     'from launch import LaunchDescription\n\n\n'
                     'def generate_launch_description():\n'
                     '    return LaunchDescription([])\n')
    shown = files.display(files.expand('~/ros2_ws/launch/empty_launch.py'))
    assert shown == '/root/ros2_ws/launch/empty_launch.py'
    r = labkit.ros2(f'launch {shown}')
    assert r.returncode == 0, r.stderr
    assert 'not found' not in r.stderr and 'No such file' not in r.stderr


def test_ros2_bag_info_of_the_printed_folder(sandbox):
    talker = labkit.ros2('run demo_nodes_py talker')
    rec = labkit.ros2('bag record -o my_bag /chatter')
    labkit.sleep(2.5)
    rec.stop()
    talker.stop()
    r = labkit.ros2('bag info /root/my_bag')
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith('\nFiles:             my_bag_0.db3\n')


def test_colcon_and_rosdep_take_the_printed_paths(sandbox):
    from labkit.ament import colcon
    files.mkdir('~/ros2_ws/src')
    files.cd('~/ros2_ws/src')
    assert labkit.ros2('pkg create --build-type ament_python --dependencies rclpy '
                       '-- my_pkg').returncode == 0
    files.cd('~')
    r = colcon.run_command('list --base-paths /root/ros2_ws/src')
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith('my_pkg\t')
    from labkit.ament import rosdep
    r = rosdep.run_command('keys --from-paths /root/ros2_ws/src')
    assert r.returncode == 0, r.stderr
    assert 'rclpy' in r.stdout.split()
