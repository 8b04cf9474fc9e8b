"""labkit's core work in one run, for tests/platform/test_encoding.py: run with
PYTHONWARNDEFAULTENCODING=1 (`-X warn_default_encoding`), any text file that labkit opens
without an encoding (or a subprocess pipe in text mode without one) raises its
EncodingWarning as an error where labkit did it. The warning is blamed on the innermost
frame outside the standard library (subprocess and io warn on their caller's behalf):
one in labkit/ is an error, one in a third-party package (cv2 opens its config so) is
only counted.

pkg create, colcon build (plain and --symlink-install), source, ros2 run, colcon test and
test-result, param dump (to a file through the magic's `>`) and load, bag record and info,
launch, tf2 view_frames, interface show, tree/cat of the sandbox home."""
import os
import sys
import sysconfig
import tempfile
import traceback
import warnings

os.environ.setdefault('LABKIT_TIME', 'virtual')
os.environ.setdefault('LABKIT_DDS', 'off')

import labkit  # noqa: E402
from labkit import ament  # noqa: E402
from labkit.cli import magics  # noqa: E402

STEPS = []
LABKIT = os.path.dirname(os.path.abspath(labkit.__file__)) + os.sep
STDLIB = os.path.normcase(sysconfig.get_paths()['stdlib']) + os.sep
# third-party packages (on Windows site-packages is inside the standard library's folder)
SITE = tuple({os.path.normcase(sysconfig.get_paths()[k]) + os.sep for k in ('purelib', 'platlib')})
THIRD_PARTY = []


def _blame(filename):
    """labkit or not: the innermost caller outside the standard library and this hook."""
    stack = traceback.extract_stack()[:-2]
    for frame in reversed(stack):
        path = os.path.normcase(os.path.abspath(frame.filename))
        if frame.filename.startswith('<') or (path.startswith(STDLIB)
                                              and not path.startswith(SITE)):
            continue
        return frame
    return None


def _on_warning(message, category, filename, lineno, file=None, line=None):
    if not issubclass(category, EncodingWarning):
        return _show(message, category, filename, lineno, file, line)
    frame = _blame(filename)
    if frame is not None and os.path.abspath(frame.filename).startswith(LABKIT):
        raise EncodingWarning(f'{message} (labkit: {frame.filename}:{frame.lineno})')
    THIRD_PARTY.append(f'{frame.filename if frame else filename}')


_show = warnings.showwarning


def check(name, result):
    code = getattr(result, 'returncode', 0)
    if code not in (0, None):
        text = getattr(result, 'stdout', '') + getattr(result, 'stderr', '')
        raise SystemExit(f'step {name} failed ({code}): {text[-2000:]}')
    STEPS.append(name)
    return result


def install():
    """EncodingWarnings on, each one blamed: an error where labkit's code is to blame."""
    if not sys.flags.warn_default_encoding:
        raise SystemExit('run with PYTHONWARNDEFAULTENCODING=1 (-X warn_default_encoding)')
    warnings.simplefilter('always', EncodingWarning)
    warnings.showwarning = _on_warning


def main():
    install()
    tmp = tempfile.mkdtemp(prefix='labkit-enc-')
    ament.use_home(os.path.join(tmp, 'home'))
    try:
        ament.mkdir('~/ros2_ws/src')
        ament.cd('~/ros2_ws/src')
        check('pkg create', labkit.ros2('pkg create --build-type ament_python '
                                        '--node-name my_node my_package'))
        check('pkg create cmake', labkit.ros2('pkg create --build-type ament_cmake my_cmake'))
        ament.cat('my_package/package.xml')
        ament.cd('~/ros2_ws')
        check('colcon build', labkit.colcon('build'))
        check('colcon build --symlink-install', labkit.colcon('build --symlink-install'))
        check('colcon list', labkit.colcon('list'))
        if labkit.source('install/setup.bash') != 0:
            raise SystemExit('step source failed')
        STEPS.append('source')
        check('ros2 run', labkit.ros2('run my_package my_node'))
        check('colcon test', labkit.colcon('test --packages-select my_package'))
        labkit.colcon('test-result --all')
        STEPS.append('colcon test-result')
        ament.tree('~/ros2_ws/log')

        job = labkit.ros2('run turtlesim turtlesim_node')
        labkit.sleep(1.0)
        magics.ros2_magic('param dump /turtlesim > turtlesim.yaml')
        STEPS.append('param dump >')
        check('param load', labkit.ros2('param load /turtlesim turtlesim.yaml'))
        bag = labkit.ros2('bag record -o my_bag /turtle1/pose')
        labkit.sleep(2.0)
        bag.stop()
        check('bag info', labkit.ros2('bag info my_bag'))
        job.stop()

        check('interface show', labkit.ros2('interface show turtlesim/srv/Spawn'))
        with open('demo.launch.xml', 'w', encoding='utf-8') as f:
            f.write('<launch>\n  <node pkg="turtlesim" exec="turtlesim_node" name="sim"/>\n'
                    '</launch>\n')
        launch = labkit.ros2('launch demo.launch.xml')
        if not hasattr(launch, 'stop'):
            check('launch', launch)
        labkit.sleep(1.0)
        launch.stop()
        STEPS.append('launch')

        tf = labkit.ros2('run tf2_ros static_transform_publisher --x 1 --frame-id world '
                         '--child-frame-id robot')
        labkit.sleep(0.5)
        check('view_frames', labkit.ros2('run tf2_tools view_frames'))
        tf.stop()
    finally:
        labkit.reset()
        ament.leave_home()
    print('steps: ' + ', '.join(STEPS))
    print(f'third-party EncodingWarnings (not labkit\'s): {len(THIRD_PARTY)}')


if __name__ == '__main__':
    sys.exit(main())
