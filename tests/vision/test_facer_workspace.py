"""The facer sources as a learner builds them: colcon build, source, ros2 run, service call."""
import os
import shutil
import sys

import pytest

import labkit
from labkit.vision import CROWD_CLIP, SAMPLE_CLIP

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


def _built(facer_ws):
    from labkit.ament import source
    assert colcon.run_command('build').returncode == 0
    assert source.run('install/setup.bash') == 0
    shutil.copy(SAMPLE_CLIP, facer_ws / 'facer_sample.avi')
    shutil.copy(CROWD_CLIP, facer_ws / 'facer_crowd.avi')


def _faces():
    out = labkit.ros2('service call /face_result facer_interfaces/srv/FaceResult '
                      '"{apply_result: true}"').stdout
    return out.split("get_result='")[1].split("'")[0]


def test_cascade_is_installed_with_the_package(facer_ws):
    _built(facer_ws)
    share = facer_ws / 'install/facer_handle/share/facer_handle'
    assert (share / 'data/haarcascade_frontalface_default.xml').is_file()
    from facer_handle.identify_image import find_cascade
    assert find_cascade() == str(share / 'data/haarcascade_frontalface_default.xml')


def test_detector_parameters_are_validated_and_take_effect(facer_ws):
    _built(facer_ws)
    labkit.ros2('run facer_input capture_image --ros-args -p source:=facer_crowd.avi '
                '-p timer_period:=0.5')
    labkit.ros2('run facer_handle identify_image')
    labkit.sleep(0.6)
    assert _faces() == '检测到 3 张人脸'      # two faces and the cell picture's false positive
    r = labkit.ros2('param set /identify_image min_neighbors 20')
    assert r.stdout == 'Set parameter successful\n'
    labkit.sleep(0.5)
    assert _faces() == '检测到 2 张人脸'      # read again on the next frame
    r = labkit.ros2('param set /identify_image min_neighbors 99')
    assert r.stderr == ('Setting parameter failed: Parameter min_neighbors out of range. '
                        'Min: 0, Max: 50, value: 99\n')
    r = labkit.ros2('param set /identify_image scale_factor 1.0')
    assert r.stderr.startswith('Setting parameter failed: Parameter scale_factor out of range')
    r = labkit.ros2('param set /identify_image min_size 10.5')
    assert r.stderr.startswith('Setting parameter failed: Wrong parameter type')
    assert labkit.ros2('param get /identify_image min_neighbors').stdout == 'Integer value is: 20\n'
    out = labkit.ros2('param describe /identify_image min_size').stdout
    assert 'Min value: 10' in out and 'Max value: 480' in out and 'Step: 1' in out


def test_bringup_launch_with_params_file(facer_ws):
    pytest.importorskip('labkit.launch')
    _built(facer_ws)
    share = facer_ws / 'install/facer_input/share/facer_input'
    assert (share / 'config/facer_params.yaml').is_file()
    labkit.ros2('launch facer_input facer_bringup_launch.py')
    labkit.sleep(0.5)
    assert labkit.ros2('node list').stdout.split() == [
        '/capture_image', '/identify_image', '/visual_interaction']
    assert labkit.ros2('param get /identify_image min_neighbors').stdout == \
        'Integer value is: 20\n'
    assert labkit.ros2('param get /capture_image source').stdout == \
        'String value is: facer_crowd.avi\n'
    labkit.sleep(0.5)
    assert _faces() == '检测到 2 张人脸'      # min_neighbors 20: no false positive
    labkit.reset()
    labkit.ros2('launch facer_input facer_bringup_launch.py source:=facer_sample.avi')
    labkit.sleep(0.3)
    assert labkit.ros2('param get /capture_image source').stdout == \
        'String value is: facer_sample.avi\n'


def test_params_file_on_the_command_line(facer_ws):
    _built(facer_ws)
    labkit.ros2('run facer_handle identify_image --ros-args --params-file '
                'src/facer_input/config/facer_params.yaml')
    labkit.sleep(0.2)
    assert labkit.ros2('param get /identify_image min_neighbors').stdout == \
        'Integer value is: 20\n'
