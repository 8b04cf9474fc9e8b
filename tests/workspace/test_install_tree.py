"""The install folder colcon writes, by its real names: the workspace's setup scripts and
_local_setup_util_*.py, each package's hooks and package.* scripts, the egg-info of
ament_python packages, ament_package()'s environment files; the scripts work in a real
shell. Also `ament.ls` hides dot files unless asked, as ls does."""
import os
import shutil
import subprocess

import pytest

from labkit.ament import colcon, files


def build(command='build'):
    r = colcon.run_command(command)
    assert r.returncode == 0, r.text()
    return r


def test_workspace_files_have_colcons_names(facer):
    build()
    inst = facer / 'install'
    names = set(os.listdir(inst))
    assert {'.colcon_install_layout', 'COLCON_IGNORE', '_local_setup_util_sh.py',
            '_local_setup_util_ps1.py'} <= names
    for stem in ('setup', 'local_setup'):
        assert {f'{stem}.{ext}' for ext in ('bash', 'sh', 'zsh', 'ps1')} <= names
    assert (inst / '.colcon_install_layout').read_text() == 'isolated\n'


def test_ament_python_package_files(facer):
    build()
    prefix = facer / 'install' / 'facer_input'
    share = prefix / 'share' / 'facer_input'
    hooks = {f'{stem}.{ext}' for stem in ('ament_prefix_path', 'pythonpath')
             for ext in ('dsv', 'sh', 'ps1')}
    assert set(os.listdir(share / 'hook')) == hooks
    for ext in ('bash', 'dsv', 'ps1', 'sh', 'zsh', 'xml'):
        assert (share / f'package.{ext}').is_file()
    # colcon's order: the default hooks (PYTHONPATH), then colcon-ros' AMENT_PREFIX_PATH
    assert (share / 'package.dsv').read_text().splitlines() == [
        f'source;share/facer_input/hook/{stem}.{ext}'
        for stem in ('pythonpath', 'ament_prefix_path') for ext in ('ps1', 'dsv', 'sh')]
    assert (share / 'hook' / 'pythonpath.dsv').read_text() == \
        'prepend-non-duplicate;PYTHONPATH;lib/python3.10/site-packages\n'
    assert (share / 'hook' / 'ament_prefix_path.dsv').read_text() == \
        'prepend-non-duplicate;AMENT_PREFIX_PATH;\n'
    assert (prefix / 'share/colcon-core/packages/facer_input').is_file()
    assert (prefix / 'share/ament_index/resource_index/packages/facer_input').is_file()
    egg = prefix / 'lib/python3.10/site-packages/facer_input-0.0.0-py3.10.egg-info'
    assert {'PKG-INFO', 'SOURCES.txt', 'dependency_links.txt', 'entry_points.txt',
            'top_level.txt', 'zip-safe'} <= set(os.listdir(egg))
    sources = (egg / 'SOURCES.txt').read_text().splitlines()
    assert 'setup.py' in sources and 'facer_input/capture_image.py' in sources
    assert '../../build/facer_input/facer_input.egg-info/PKG-INFO' in sources
    assert sources == sorted(sources)


def test_ament_cmake_package_files(facer):
    build()
    share = facer / 'install' / 'facer_interfaces' / 'share' / 'facer_interfaces'
    assert set(os.listdir(share / 'hook')) == {
        f'cmake_prefix_path.{ext}' for ext in ('dsv', 'sh', 'ps1')}
    for ext in ('bash', 'dsv', 'sh', 'zsh'):
        assert (share / f'local_setup.{ext}').is_file()
    assert (share / 'environment' / 'ament_prefix_path.dsv').read_text() == \
        'prepend-non-duplicate;AMENT_PREFIX_PATH;\n'
    assert (share / 'cmake' / 'facer_interfacesConfig.cmake').is_file()
    listed = (share / 'package.dsv').read_text().splitlines()
    assert listed[-4:] == [f'source;share/facer_interfaces/local_setup.{ext}'
                           for ext in ('bash', 'dsv', 'sh', 'zsh')]


def test_symlink_install_puts_the_build_folder_on_pythonpath(facer):
    build('build --symlink-install --packages-select facer_input')
    hook = facer / 'install/facer_input/share/facer_input/hook/pythonpath_develop.dsv'
    assert hook.read_text() == ('prepend-non-duplicate;PYTHONPATH;%s\n'
                                % (facer / 'build' / 'facer_input'))


def _shell(shell, script, cwd):
    env = {'PATH': os.environ.get('PATH', '/usr/bin:/bin'), 'HOME': str(cwd)}
    done = subprocess.run([shell, '-c', script], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return dict(line.split('=', 1) for line in done.stdout.splitlines() if '=' in line)


@pytest.mark.parametrize('shell,script', [('bash', 'install/setup.bash'),
                                          ('sh', 'install/setup.sh'),
                                          ('bash', 'install/local_setup.bash')])
def test_setup_scripts_work_in_a_real_shell(facer, shell, script):
    if shutil.which(shell) is None:
        pytest.skip(f'no {shell} on this machine')
    build()
    inst = facer / 'install'
    # sourced twice: nothing is added twice
    got = _shell(shell, f'. {script}; . {script}; for v in AMENT_PREFIX_PATH PYTHONPATH '
                 'COLCON_PREFIX_PATH CMAKE_PREFIX_PATH; do eval echo "$v=\\$$v"; done',
                 facer)
    # dependencies first, so the last package built comes first in the path
    assert got['AMENT_PREFIX_PATH'].split(':') == [
        str(inst / p) for p in ('facer_bringup', 'facer_detect', 'facer_interfaces',
                                'facer_input')]
    assert got['PYTHONPATH'].split(':') == [
        str(inst / p / 'lib/python3.10/site-packages')
        for p in ('facer_bringup', 'facer_detect', 'facer_input')]
    assert got['COLCON_PREFIX_PATH'] == str(inst)
    assert got['CMAKE_PREFIX_PATH'] == str(inst / 'facer_interfaces')


def test_local_setup_util_prints_the_commands_in_order(facer):
    build()
    done = subprocess.run(['python3', str(facer / 'install' / '_local_setup_util_sh.py'),
                           'sh'], capture_output=True, text=True, timeout=120)
    packages = [line.split(': ')[1] for line in done.stdout.splitlines()
                if line.startswith('# package: ')]
    assert packages == ['facer_input', 'facer_interfaces', 'facer_detect', 'facer_bringup']
    assert ('_colcon_prepend_unique_value PYTHONPATH "%s"'
            % (facer / 'install/facer_input/lib/python3.10/site-packages')) in done.stdout


def test_ls_hides_dot_files_unless_asked(facer, capsys):
    build()
    files.ls('install')
    shown = capsys.readouterr().out.split()
    assert 'COLCON_IGNORE' in shown and 'facer_input' in shown
    assert not any(name.startswith('.') for name in shown)
    files.ls('-A', 'install')
    assert '.colcon_install_layout' in capsys.readouterr().out.split()
    files.ls('-a', 'install')
    everything = capsys.readouterr().out.split()
    assert everything[:3] == ['.', '..', '.colcon_install_layout']
    files.ls('install', all=True)
    assert '.colcon_install_layout' in capsys.readouterr().out.split()
    with pytest.raises(ValueError, match='ament.ls knows -a and -A, not -l'):
        files.ls('-l')
