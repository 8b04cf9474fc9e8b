"""The facer robot exactly as the reader builds it in chapters 12-15.

Every `%%writefile` cell of ch12-ch15 (the chapter text, not the exercises or
ch12's "动手实验" detour) is replayed in order into a fresh sandbox home, with
the `ament.cd(...)` and `ros2 pkg create` lines around them, and the same
copies from facer_src that each chapter's first cell makes (so a chapter read
on its own starts where the previous one ended). The workspace is then built
with labkit's colcon, sourced, and the three nodes run on the sample clip in
virtual time.
"""
import filecmp
import json
import os
import re
import shutil

import pytest

import labkit
from labkit import ament
from labkit.graph import world
from labkit.vision import SAMPLE_CLIP

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PART2 = os.path.join(REPO, 'book', 'part2_facer')
FACER_SRC = os.path.join(PART2, 'facer_src', 'src')
CHAPTERS = ['ch12_interfaces', 'ch13_nodes', 'ch14_node_tasks', 'ch15_parameters']
ALL_PACKAGES = ('facer_interfaces', 'facer_input', 'facer_handle', 'facer_output')
# what each chapter's first cell copies from facer_src (see the notebooks)
COPIES = {
    'ch13_nodes': (('facer_interfaces',), ()),
    'ch14_node_tasks': (ALL_PACKAGES, ('capture_image.py', 'identify_image.py',
                                       'visual_interaction.py', 'launch', 'data', 'config')),
    'ch15_parameters': (ALL_PACKAGES, ('capture_image.py', 'identify_image.py', 'launch',
                                       'config')),
}
CD = re.compile(r"^ament\.cd\('([^']*)'\)")
PKG_CREATE = re.compile(r"^(?:%ros2 |labkit\.ros2\(')(pkg create [^')]*)")


def chapter_steps(name):
    """(kind, argument) steps of one chapter's text: cd, pkg create, writefile."""
    with open(os.path.join(PART2, name + '.ipynb'), encoding='utf-8') as f:
        cells = json.load(f)['cells']
    steps = []
    for cell in cells:
        source = ''.join(cell['source'])
        if cell['cell_type'] == 'markdown':
            if re.search(r'^#+ (练习|动手实验)', source, re.M):
                break               # exercises and side experiments are not the robot
            continue
        if source.startswith('%%writefile '):
            first, _, body = source.partition('\n')
            steps.append(('write', (first.split(None, 1)[1].strip(), body)))
            continue
        for line in source.splitlines():
            line = line.strip()
            if CD.match(line):
                steps.append(('cd', CD.match(line).group(1)))
            elif PKG_CREATE.match(line):
                steps.append(('ros2', PKG_CREATE.match(line).group(1)))
    return steps


def replay(home):
    """Rebuild ~/facer_ws from the chapters; returns the number of files written."""
    written = 0
    for name in CHAPTERS:
        packages, ignore = COPIES.get(name, ((), ()))
        for package in packages:
            shutil.copytree(os.path.join(FACER_SRC, package),
                            os.path.join(home, 'facer_ws', 'src', package),
                            ignore=shutil.ignore_patterns(*ignore), dirs_exist_ok=True)
        os.makedirs(os.path.join(home, 'facer_ws', 'src'), exist_ok=True)
        os.chdir(home)
        for kind, arg in chapter_steps(name):
            if kind == 'cd':
                os.makedirs(ament.files.expand(arg), exist_ok=True)
                ament.cd(arg)
            elif kind == 'ros2':
                target = arg.split()[-1]
                if not os.path.exists(target):  # later chapters' copies may have made it
                    assert labkit.ros2(arg).returncode == 0, arg
            else:
                path, body = arg
                folder = os.path.dirname(path)
                if folder:
                    os.makedirs(folder, exist_ok=True)
                with open(path, 'w', encoding='utf-8') as f:
                    f.write(body if body.endswith('\n') else body + '\n')
                written += 1
    return written


@pytest.fixture(scope='module')
def facer_ws(tmp_path_factory):
    """The chapters' workspace, built and sourced once for the module."""
    from labkit import compat, executables, plugins
    from labkit.interfaces import registry
    import labkit.vision
    plugins.register_all()
    mp = pytest.MonkeyPatch()
    for var in ('AMENT_PREFIX_PATH', 'PYTHONPATH', 'COLCON_PREFIX_PATH'):
        mp.delenv(var, raising=False)
    was_active = compat.is_active()
    compat.activate(quiet=True)
    labkit.vision.register()
    import sys
    saved_path, saved_exe = list(sys.path), dict(executables._extra)
    saved_roots = registry.share_paths()
    cwd = os.getcwd()
    home = str(tmp_path_factory.mktemp('home'))
    ament.use_home(home)
    try:
        written = replay(home)
        shutil.copy(SAMPLE_CLIP, os.path.join(home, 'facer_sample.avi'))
        ament.cd('~/facer_ws')
        build = labkit.colcon('build')
        assert build.returncode == 0, build.stdout + build.stderr
        assert labkit.source('install/setup.bash') == 0
        ament.cd('~')
        yield home, written
    finally:
        labkit.reset()
        ament.leave_home(remove=False)
        os.chdir(cwd)
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
        mp.undo()


@pytest.fixture
def graph(facer_ws):
    labkit.reset()
    world.set_mode('virtual')
    yield facer_ws[0]
    labkit.reset()


def _camera(timer_period):
    return labkit.ros2('run facer_input capture_image --ros-args '
                       f'-p source:=facer_sample.avi -p timer_period:={timer_period}')


def _ask():
    out = labkit.ros2('service call /face_result facer_interfaces/srv/FaceResult '
                      '"{apply_result: true}"').stdout
    return re.search(r"get_result='([^']*)'", out).group(1)


def test_chapters_write_the_reference_robot(facer_ws):
    home, written = facer_ws
    assert written >= 25
    src = os.path.join(home, 'facer_ws', 'src')
    for rel in ['facer_input/facer_input/capture_image.py',
                'facer_input/launch/python_parameters_launch.py',
                'facer_input/setup.py', 'facer_input/package.xml',
                'facer_handle/facer_handle/identify_image.py', 'facer_handle/package.xml',
                'facer_handle/setup.py', 'facer_input/config/facer_params.yaml',
                'facer_input/launch/facer_bringup_launch.py',
                'facer_output/facer_output/visual_interaction.py', 'facer_output/package.xml',
                'facer_interfaces/CMakeLists.txt', 'facer_interfaces/package.xml',
                'facer_interfaces/srv/FaceResult.srv', 'facer_interfaces/action/CameraState.action']:
        assert filecmp.cmp(os.path.join(src, rel), os.path.join(FACER_SRC, rel), shallow=False), rel
    share = os.path.join(home, 'facer_ws', 'install', 'facer_input', 'share', 'facer_input')
    assert os.path.isfile(os.path.join(share, 'launch', 'python_parameters_launch.py'))
    assert os.path.isfile(os.path.join(share, 'config', 'facer_params.yaml'))
    handle = os.path.join(home, 'facer_ws', 'install', 'facer_handle', 'share', 'facer_handle')
    assert os.path.isfile(os.path.join(handle, 'data', 'haarcascade_frontalface_default.xml'))


def test_face_result_follows_the_frames(graph):
    _camera(0.5)               # frame k goes out at 0.5 (k + 1): 0-5 a face, 6-11 none
    labkit.ros2('run facer_handle identify_image')
    labkit.sleep(0.6)
    assert _ask() == '检测到 1 张人脸'
    labkit.sleep(3.0)          # now past frame 6
    assert _ask() == '未检测到人脸'


def test_camera_state_gives_feedback_then_result(graph):
    _camera(0.5)
    out = labkit.ros2('action send_goal /camera_state facer_interfaces/action/CameraState '
                      '"{start: true}" --feedback').stdout
    assert out.count('Feedback:\n    state: 摄像头打开') == 10
    assert out.index('Result:\n    finish: action completed') > out.rindex('Feedback:')
    assert 'Goal finished with status: SUCCEEDED' in out


def _rate(seconds):
    job = labkit.ros2('topic hz /frame_image')
    labkit.sleep(seconds)
    job.stop()
    rates = re.findall(r'average rate: ([0-9.]+)', job.stdout)
    return float(rates[-1])


def test_timer_period_change_alters_the_frame_rate(graph):
    _camera(0.5)
    assert _rate(3) == pytest.approx(2.0, abs=0.05)
    assert labkit.ros2('param set /capture_image timer_period 1.0').stdout.strip() == \
        'Set parameter successful'
    assert _rate(4) == pytest.approx(1.0, abs=0.05)


def test_visual_interaction_talks_to_both_servers(graph):
    _camera(0.5)
    labkit.ros2('run facer_handle identify_image')
    viewer = labkit.ros2('run facer_output visual_interaction')
    labkit.sleep(1.6)
    out = viewer.stdout
    assert '[visual_interaction]: 识别结果：检测到 1 张人脸' in out
    assert '[visual_interaction]: 目标请求成功' in out
    assert '[visual_interaction]: 摄像头状态：摄像头打开' in out


def _cell_sources(name):
    with open(os.path.join(PART2, name + '.ipynb'), encoding='utf-8') as f:
        return [''.join(c['source']) for c in json.load(f)['cells'] if c['cell_type'] == 'code']


def _run_check(source):
    """Run a chapter's check cell; returns the Checker it built (its report goes to stdout)."""
    namespace = {'labkit': labkit, 'ament': ament}
    exec(compile(source, 'check', 'exec'), namespace)
    return namespace['c']


def test_exercise_15_1_check_catches_the_node_that_ignores_the_change(graph, tmp_path, capsys):
    """15.3.1's trap: a capture_image without a parameters callback. Its parameter says 0.2,
    its timer still ticks every 0.1 s: the check of exercise 15.1 must fail on it."""
    from labkit import process
    cells = _cell_sources('ch15_parameters')
    check = [s for s in cells if "Checker('练习 15.1')" in s][0]
    first = [s for s in cells if s.startswith(
        '%%writefile src/facer_input/facer_input/capture_image.py')][0]
    assert 'add_on_set_parameters_callback' not in first
    path = tmp_path / 'capture_no_callback.py'
    path.write_text(first.partition('\n')[2], encoding='utf-8')
    import importlib.util
    spec = importlib.util.spec_from_file_location('capture_no_callback', path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    process.start(name='capture_image', main=module.main, echo=False,
                  args=['capture_image', '--ros-args', '-p', 'source:=facer_sample.avi'])
    labkit.sleep(0.3)
    assert labkit.ros2('param set /capture_image timer_period 0.2').stdout.strip() == \
        'Set parameter successful'
    c = _run_check(check)
    assert not c.passed
    assert '参数改了，定时器也跟着改了吗？' in capsys.readouterr().out
    labkit.reset()
    _camera(0.1)                              # the chapter's final node: the check passes
    labkit.sleep(0.3)
    labkit.ros2('param set /capture_image timer_period 0.2')
    assert _run_check(check).passed
