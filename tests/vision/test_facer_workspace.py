"""The facer sources as a learner builds them: colcon build, source, ros2 run, service call."""
import os
import shutil
import sys

import pytest

import labkit
from labkit.vision import SAMPLE_CLIP

FACER_SRC = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..',
                         'book', 'part2_facer', 'facer_src', 'src')

colcon = pytest.importorskip('labkit.ament.colcon')


@pytest.fixture
def facer_ws(tmp_path, monkeypatch, virtual):
    from labkit import compat, executables
    from labkit.interfaces import registry
    for var in ('AMENT_PREFIX_PATH', 'PYTHONPATH', 'COLCON_PREFIX_PATH'):
        monkeypatch.delenv(var, raising=False)
    was_active = compat.is_active()
    compat.activate(quiet=True)
    saved_path, saved_exe = list(sys.path), dict(executables._extra)
    saved_roots = registry.share_paths()
    ws = tmp_path / 'facer_ws'
    shutil.copytree(FACER_SRC, ws / 'src')
    monkeypatch.chdir(ws)
    yield ws
    labkit.reset()
    sys.path[:] = saved_path
    executables._extra.clear()
    executables._extra.update(saved_exe)
    for root in registry.share_paths():
        if root not in saved_roots:
            registry.remove_share_path(root)
    for key in [k for k in sys.modules if k.startswith('facer_')]:
        del sys.modules[key]
    if not was_active:
        compat.deactivate()


def test_build_source_run_call(facer_ws):
    from labkit.ament import source
    result = colcon.run_command('build')
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout.splitlines()[-2].startswith('Summary: 4 packages finished')
    assert result.stdout.splitlines()[-1] == \
        '  3 packages had stderr output: facer_handle facer_input facer_output'
    assert (facer_ws / 'install/facer_input/share/facer_input/launch/'
            'python_parameters_launch.py').is_file()
    assert source.run('install/setup.bash') == 0
    interfaces = labkit.ros2('interface package facer_interfaces').stdout.split()
    assert interfaces == ['facer_interfaces/action/CameraState', 'facer_interfaces/srv/FaceResult']
    labkit.ros2('run facer_input capture_image --ros-args -p timer_period:=0.5 '
                '-p source:=' + SAMPLE_CLIP)
    labkit.ros2('run facer_handle identify_image')
    labkit.sleep(0.6)
    out = labkit.ros2('service call /face_result facer_interfaces/srv/FaceResult '
                      '"{apply_result: true}"').stdout
    assert "facer_interfaces.srv.FaceResult_Response(get_result='检测到 1 张人脸')" in out
    nodes = labkit.ros2('node list').stdout.split()
    assert nodes == ['/capture_image', '/identify_image']
    topics = labkit.ros2('topic list -t').stdout.splitlines()
    assert '/frame_image [sensor_msgs/msg/Image]' in topics
    assert '/face_image [sensor_msgs/msg/Image]' in topics


def test_launch_file_sets_timer_period(facer_ws):
    pytest.importorskip('labkit.launch')
    from labkit.ament import source
    assert colcon.run_command('build').returncode == 0
    assert source.run('install/setup.bash') == 0
    job = labkit.ros2('launch facer_input python_parameters_launch.py')
    labkit.sleep(0.2)
    out = labkit.ros2('param get /capture_image timer_period')
    assert out.stdout == 'Double value is: 1.0\n', (out.stdout, out.stderr, job)
