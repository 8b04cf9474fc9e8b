"""The import hook must not import numpy from inside someone's `import numpy`: numpy would
be executed twice and `numpy.linalg` would recurse forever (ch23's first matplotlib cell
in a kernel where nothing had imported numpy before `%load_ext labkit`)."""
import subprocess
import sys

PROGRAM = '''
import labkit.plugins, labkit.compat
labkit.plugins.register_all = lambda: None     # only the hook: nothing imports numpy first
assert "numpy" not in __import__("sys").modules
labkit.compat.activate()
import numpy
print(numpy.linalg.norm([3.0, 4.0]))
'''


def test_numpy_imports_once_under_the_hook():
    done = subprocess.run([sys.executable, '-c', PROGRAM], capture_output=True, text=True,
                          timeout=120, env={'LABKIT_TIME': 'virtual', 'PATH': '/usr/bin:/bin'})
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout == '5.0\n'
    assert 'reloaded' not in done.stderr
