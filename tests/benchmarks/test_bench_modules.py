"""Every benchmarks/*.py can run from `make bench`: each module imports, runs something as a script, and
every import it makes anywhere (also inside functions, which only run under `make bench`)
names a module and a name that exist. A benchmark that imported a helper removed from the
tests (bench_launch.py and tests/launch/conftest.py's install_launch_tutorial) stopped
`make bench` before the seven benchmarks after it; this test fails on such a module.
"""
import ast
import importlib
import importlib.util
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SCRIPTS = sorted((REPO / 'benchmarks').glob('*.py'))
# Modules that exist only on the reference side (real rclpy's interpreter) or only on
# other operating systems; the benchmarks import them in a subprocess of that interpreter.
ELSEWHERE = {'rclpy._rclpy_pybind11', 'winreg', 'msvcrt'}


def load(script):
    spec = importlib.util.spec_from_file_location('bench_' + script.stem, script)
    module = importlib.util.module_from_spec(spec)
    saved = list(sys.path)
    try:
        spec.loader.exec_module(module)
    finally:
        added = [p for p in sys.path if p not in saved]
        sys.path[:] = saved
    return module, added


def imports(script):
    """(module, name or None, line) of every import statement in the file."""
    tree = ast.parse(script.read_text(encoding='utf-8'))
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield alias.name, None, node.lineno
        elif isinstance(node, ast.ImportFrom) and node.level == 0:
            for alias in node.names:
                yield node.module, alias.name, node.lineno


def own_package(module, name):
    """A package the benchmark puts on sys.path itself at run time (e.g. bench_facer.py
    the book's facer_src/src/<pkg>): it exists under a folder the module names."""
    top = name.split('.')[0]
    for value in vars(module).values():
        if isinstance(value, Path) and value.is_dir():
            if (value / top / top / '__init__.py').is_file() or \
                    (value / top / '__init__.py').is_file():
                return True
    return False


@pytest.fixture(scope='module')
def rclpy_names():
    """labkit's rclpy, std_msgs, ... importable as they are under `labkit exec`."""
    from labkit import compat
    compat.activate(quiet=True)
    yield


def test_every_benchmark_is_listed():
    names = {s.name for s in SCRIPTS}
    assert {'bench_launch.py', 'bench_pubsub.py', 'bench_dds.py'} <= names
    assert len(SCRIPTS) >= 14


@pytest.mark.parametrize('script', [s for s in SCRIPTS if not s.name.startswith('_')],
                         ids=lambda s: s.name)
def test_benchmark_imports_resolve(script, rclpy_names):
    module, added = load(script)
    assert "if __name__ == '__main__'" in script.read_text(encoding='utf-8').replace('"', "'"), \
        f'{script.name} does nothing when make bench runs it'
    saved = list(sys.path)
    sys.path[:0] = added + [str(REPO / 'benchmarks')]
    try:
        for name, attr, line in imports(script):
            if name in ELSEWHERE or name.split('.')[0] in ELSEWHERE:
                continue
            try:
                target = importlib.import_module(name)
            except ImportError as error:
                if own_package(module, name):
                    continue
                pytest.fail(f'{script.name}:{line}: import {name}: {error}')
            if attr is not None and attr != '*' and not hasattr(target, attr):
                try:
                    importlib.import_module(f'{name}.{attr}')
                except ImportError:
                    pytest.fail(f'{script.name}:{line}: cannot import name {attr!r} '
                                f'from {name!r}')
    finally:
        sys.path[:] = saved
