"""colcon build of a 4-package facer-like workspace (1 interface package, 3 ament_python),
clean and then incremental, plus `source`: five runs each, median (target < 3 s).

    python benchmarks/bench_colcon.py

Measured wall-clock time of labkit's build (live mode), not the cost-model times
colcon prints in virtual mode.
"""
import json
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
sys.path.insert(0, str(REPO / 'tests' / 'workspace'))
RUNS = 5


def main():
    os.environ.setdefault('LABKIT_TIME', 'live')
    import facer_ws
    import labkit.ament  # noqa: F401
    from labkit.ament import colcon, source
    clean, incremental, sourcing = [], [], []
    cwd = os.getcwd()
    saved_env = os.environ.get('AMENT_PREFIX_PATH')
    try:
        for _ in range(RUNS):
            with tempfile.TemporaryDirectory() as ws:
                facer_ws.facer_workspace(ws)
                os.chdir(ws)
                t0 = time.perf_counter()
                result = colcon.run_command('build')
                clean.append(time.perf_counter() - t0)
                assert result.returncode == 0, result.text()
                t0 = time.perf_counter()
                colcon.run_command('build --packages-select facer_input')
                incremental.append(time.perf_counter() - t0)
                t0 = time.perf_counter()
                source.source('install/setup.bash')
                sourcing.append(time.perf_counter() - t0)
                os.chdir(cwd)
    finally:
        os.chdir(cwd)
        if saved_env is None:
            os.environ.pop('AMENT_PREFIX_PATH', None)
    figures = {
        'colcon_build_4_packages_s': round(statistics.median(clean), 4),
        'colcon_build_one_package_s': round(statistics.median(incremental), 4),
        'source_s': round(statistics.median(sourcing), 4),
        'goal_s': 3.0,
    }
    figures['meets_goal'] = figures['colcon_build_4_packages_s'] < figures['goal_s']
    print(json.dumps(figures))


if __name__ == '__main__':
    main()
