"""rosdep over the bundled key tables: resolution, -i, unknown keys, honest output."""
from labkit.ament import rosdep


def test_install_ignore_src_resolves_every_key(facer):
    r = rosdep.run_command('install -i --from-path src --rosdistro humble -y')
    assert r.returncode == 0, r.text()
    lines = r.stdout.splitlines()
    assert lines[-1] == '#All required rosdeps installed successfully'
    assert '#[apt] ros-humble-rclpy' in lines
    assert '#[apt] python3-opencv' in lines           # facer_detect's exec_depend
    assert '#[apt] ros-humble-rosidl-default-generators' in lines
    assert not any('apt-get install' in line for line in lines)   # nothing pretends to install
    assert not any('facer_' in line for line in lines)            # workspace keys skipped
    same = rosdep.run_command('install --from-paths src -y --ignore-src')
    assert same.stdout == r.stdout


def test_without_ignore_src_workspace_packages_are_unknown_keys(facer):
    r = rosdep.run_command('install --from-paths src -y')
    assert r.returncode == 1
    assert r.stderr.startswith(
        'ERROR: the following packages/stacks could not have their rosdep keys resolved\n'
        'to system dependencies:\n')
    assert 'facer_detect: Cannot locate rosdep definition for [facer_interfaces]' in r.stderr
    assert 'successfully' not in r.stdout


def test_python2_key_is_unknown_and_r_continues(facer):
    path = facer / 'src/facer_detect/package.xml'
    path.write_text(path.read_text().replace('python3-opencv', 'python-opencv'))
    r = rosdep.run_command('install -i --from-paths src -y')
    assert r.returncode == 1
    assert 'facer_detect: Cannot locate rosdep definition for [python-opencv]' in r.stderr
    r = rosdep.run_command('install -i --from-paths src -y -r')
    assert r.returncode == 0
    assert 'Continuing to install resolvable dependencies...' in r.stderr
    assert r.stdout.endswith('#All required rosdeps installed successfully\n')


def test_resolve_keys_and_check(facer):
    r = rosdep.run_command('resolve cv_bridge python3-numpy')
    assert r.stdout == '#apt\nros-humble-cv-bridge\n#apt\npython3-numpy\n'
    r = rosdep.run_command('resolve python-numpy')
    assert r.returncode == 1 and "no rosdep rule for 'python-numpy'" in r.stderr
    keys = rosdep.run_command('keys --from-paths src -i').stdout.split()
    assert 'geometry_msgs' in keys and 'facer_interfaces' not in keys
    assert rosdep.run_command('check --from-paths src -i').stdout == \
        'All system dependencies have been satisfied\n'


def test_help_init_update_say_what_they_would_do():
    assert 'rosdep install <stacks-and-packages>...' in rosdep.run_command('-h').stdout
    assert '20-default.list' in rosdep.run_command('init').stdout
    assert 'nothing was downloaded' in rosdep.run_command('update').stdout
    r = rosdep.run_command('frobnicate')
    assert r.returncode == 2 and r.stderr.endswith('rosdep: error: Unsupported command frobnicate.\n')


def test_help_is_optparse_as_real_rosdep_prints_it():
    out = rosdep.run_command('-h').stdout
    # optparse: the whole usage text with its Commands list, then "Options:"
    assert out.startswith('Usage: rosdep [options] <command> <args>\n\nCommands:\n')
    assert '\n\nOptions:\n  -h, --help            show this help message and exit\n' in out
    assert '  --rosdistro=ROS_DISTRO\n' in out and '  --from-paths          Affects' in out
    assert 'rosdep what-needs <rosdeps>...' in out and 'rosdep search' not in out  # 0.25, not 0.26
    assert 'usage:' not in out and 'options:' not in out
    assert max(len(line) for line in out.splitlines()) <= 78


def test_option_prefixes_and_errors_are_optparse():
    # optparse accepts unambiguous prefixes: --from-path is --from-paths
    assert rosdep.run_command('keys --from-path src').returncode == 0
    r = rosdep.run_command('--bogus')
    assert r.returncode == 2 and r.stderr.endswith('rosdep: error: no such option: --bogus\n')
    r = rosdep.run_command('')
    assert r.returncode == 2 and r.stderr.endswith('rosdep: error: Please enter a command\n')
    assert rosdep.run_command('--version').stdout == '0.25.1\n'


def test_dependency_types_select_tags(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    pkg = tmp_path / 'src' / 'demo'
    pkg.mkdir(parents=True)
    (pkg / 'package.xml').write_text(
        '<?xml version="1.0"?>\n<package format="3"><name>demo</name><version>0.0.0</version>'
        '<description>d</description><maintainer email="dev@example.com">dev</maintainer>'
        '<license>MIT</license><buildtool_depend>ament_cmake</buildtool_depend>'
        '<depend>rclpy</depend><exec_depend>python3-opencv</exec_depend>'
        '<test_depend>python3-pytest</test_depend><doc_depend>doxygen</doc_depend>'
        '<export><build_type>ament_cmake</build_type></export></package>\n')

    def keys(extra=''):
        r = rosdep.run_command('keys --from-paths src ' + extra)
        assert r.returncode == 0, r.stderr
        return r.stdout.split()
    # default: everything but doc
    assert keys() == ['ament_cmake', 'rclpy', 'python3-opencv', 'python3-pytest']
    assert keys('-t exec') == ['rclpy', 'python3-opencv']          # <depend> includes exec
    assert keys('-t build') == ['rclpy']
    assert keys('-t test') == ['python3-pytest']
    assert keys('-t doc') == ['doxygen']
    assert keys('-t exec -t test') == ['rclpy', 'python3-opencv', 'python3-pytest']
    r = rosdep.run_command('keys --from-paths src -t runtime')
    assert r.returncode == 2 and "option -t: invalid choice: 'runtime'" in r.stderr
