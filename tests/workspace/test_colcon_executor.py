"""colcon build's executors: which package starts and ends when (virtual time, 2 cores)."""
import facer_ws

from labkit.ament import colcon


def starts_and_ends(result):
    return [line.split(' [')[0] for line in result.stdout.splitlines()
            if line.startswith(('Starting >>> ', 'Finished <<< ', 'Failed   <<< ',
                                'Aborted  <<< '))]


def two_independent(ws, broken=None):
    src = str(ws / 'src')
    for name in ('pkg_a', 'pkg_b'):
        facer_ws.python_package(src, name, [], deps=[('depend', 'rclpy')])
    if broken:
        facer_ws.write(str(ws / 'src' / broken), 'setup.py', 'this is not python\n')


def test_parallel_executor_starts_independent_packages_together(ws):
    two_independent(ws)
    r = colcon.run_command('build')
    assert r.returncode == 0, r.text()
    assert starts_and_ends(r) == ['Starting >>> pkg_a', 'Starting >>> pkg_b',
                                  'Finished <<< pkg_a', 'Finished <<< pkg_b']
    # both ran at the same time: the whole build took about as long as one package
    times = [line.split('[')[1].rstrip(']') for line in r.stdout.splitlines()
             if line.startswith('Finished')]
    assert times[0] == times[1]
    summary = float(r.stdout.split('Summary: 2 packages finished [')[1].split('s]')[0])
    assert summary < 2 * float(times[0].rstrip('s'))


def test_sequential_executor_and_one_worker_keep_one_at_a_time(ws):
    two_independent(ws)
    one_by_one = ['Starting >>> pkg_a', 'Finished <<< pkg_a',
                  'Starting >>> pkg_b', 'Finished <<< pkg_b']
    assert starts_and_ends(colcon.run_command('build --executor sequential')) == one_by_one
    assert starts_and_ends(colcon.run_command('build --parallel-workers 1')) == one_by_one


def test_more_dependents_start_first_and_dependents_wait(facer):
    r = colcon.run_command('build')
    assert starts_and_ends(r) == [
        'Starting >>> facer_interfaces', 'Starting >>> facer_input',
        'Finished <<< facer_input', 'Finished <<< facer_interfaces',
        'Starting >>> facer_detect', 'Finished <<< facer_detect',
        'Starting >>> facer_bringup', 'Finished <<< facer_bringup']


def test_a_failure_aborts_the_package_running_beside_it(ws):
    two_independent(ws, broken='pkg_a')
    r = colcon.run_command('build')
    assert r.returncode != 0
    assert starts_and_ends(r) == ['Starting >>> pkg_a', 'Starting >>> pkg_b',
                                  'Failed   <<< pkg_a', 'Aborted  <<< pkg_b']
    assert '  1 package failed: pkg_a\n  1 package aborted: pkg_b\n' in r.stdout
    r = colcon.run_command('build --continue-on-error')
    assert starts_and_ends(r) == ['Starting >>> pkg_a', 'Starting >>> pkg_b',
                                  'Failed   <<< pkg_a', 'Finished <<< pkg_b']
