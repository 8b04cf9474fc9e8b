"""`ros2 run` with bad --ros-args ends as the real program ends (issue 13): a C++ executable
dies through std::terminate (rclcpp's exception class and what()), SIGABRT, and ros2 run
says "Aborted"; a Python one prints rclpy's exception. Never a labkit path or traceback."""
import pytest

import labkit
from labkit import executables, plugins

plugins.register_all()          # every room's executables, C++ ones among them

TERMINATE = "terminate called after throwing an instance of '{}'\n  what():  {}\n"


@pytest.fixture(autouse=True)
def _clean():
    labkit.reset()
    yield
    labkit.reset()


def _assert_no_labkit(result):
    text = result.stdout + result.stderr
    assert 'labkit' not in text and 'Traceback' not in text and '.py"' not in text


def test_turtlesim_bad_parameter_type_is_rclcpps_terminate():
    r = labkit.ros2('run turtlesim turtlesim_node --ros-args -p background_r:=abc')
    assert r.returncode == -6
    assert r.stderr == TERMINATE.format(
        'rclcpp::exceptions::InvalidParameterTypeException',
        "parameter 'background_r' has invalid type: Wrong parameter type, parameter "
        "{background_r} is of type {integer}, setting it to {string} is not allowed.")
    assert r.stdout == '[ros2run]: Aborted\n'
    assert r.text().endswith('[ros2run]: Aborted\n')       # after the C++ lines
    _assert_no_labkit(r)


def test_turtlesim_unknown_ros_argument():
    r = labkit.ros2('run turtlesim turtlesim_node --ros-args --frob')
    assert r.returncode == -6
    assert r.stderr == TERMINATE.format('rclcpp::exceptions::UnknownROSArgsError',
                                        "found unknown ROS arguments: '--frob'")
    _assert_no_labkit(r)


def test_turtlesim_bad_node_name_remap():
    r = labkit.ros2('run turtlesim turtlesim_node --ros-args -r __node:=1bad')
    assert r.returncode == -6
    lines = r.stderr.splitlines()
    assert lines[0].endswith('[rcl]: Failed to parse global arguments')
    assert lines[1] == ("terminate called after throwing an instance of "
                        "'rclcpp::exceptions::RCLInvalidROSArgsError'")
    assert lines[2].startswith("  what():  failed to initialize rcl: Couldn't parse remap rule: "
                               "'-r __node:=1bad'.")
    assert r.stdout == '[ros2run]: Aborted\n'
    _assert_no_labkit(r)


@pytest.mark.parametrize('package, executable', sorted(
    pair for pair in executables.executables() if executables.is_cpp(*pair)))
def test_every_builtin_cpp_executable_dies_like_rclcpp(package, executable):
    r = labkit.ros2(f'run {package} {executable} --ros-args --frob')
    assert r.returncode == -6, r.text()
    assert r.stderr.endswith(TERMINATE.format('rclcpp::exceptions::UnknownROSArgsError',
                                              "found unknown ROS arguments: '--frob'"))
    _assert_no_labkit(r)


def test_python_executable_prints_rclpys_exception():
    r = labkit.ros2('run demo_nodes_py talker --ros-args --frob')
    assert r.returncode == 1
    assert r.stderr == "rclpy._rclpy_pybind11.UnknownROSArgsError: ['--frob']\n"
    assert r.stdout == '[ros2run]: Process exited with failure 1\n'
    _assert_no_labkit(r)


def test_a_programs_own_frames_stay_in_its_traceback(tmp_path):
    # a learner's own node keeps the frames of their file (that is what they debug)
    mod = tmp_path / 'learner_node_mod.py'
    mod.write_text('def main(args=None):\n    raise ValueError("my bug")\n')
    import sys
    sys.path.insert(0, str(tmp_path))
    try:
        executables.register('learner_pkg', 'learner_node', 'learner_node_mod:main')
        main = executables.resolve(executables.lookup('learner_pkg', 'learner_node'))
        import io
        import contextlib
        err = io.StringIO()
        with contextlib.redirect_stderr(err):
            assert main() == 1
        text = err.getvalue()
        assert text.startswith('Traceback (most recent call last):\n')
        assert 'learner_node_mod.py", line 2, in main' in text
        assert text.endswith('ValueError: my bug\n')
        assert 'labkit' not in text
    finally:
        executables.unregister_package('learner_pkg')
        sys.path.remove(str(tmp_path))
