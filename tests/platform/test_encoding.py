"""Every text file labkit opens is UTF-8 (a Chinese Windows' default is GBK): labkit's
core work runs with PYTHONWARNDEFAULTENCODING=1 and fails on any EncodingWarning that
labkit's own code causes (tests/platform/encoding_workflow.py)."""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
WORKFLOW = os.path.join(HERE, 'encoding_workflow.py')


def _run(args, cwd=HERE):
    env = dict(os.environ, PYTHONWARNDEFAULTENCODING='1', LABKIT_TIME='virtual',
               LABKIT_DDS='off', PYTHONPATH=os.pathsep.join([ROOT, HERE]),
               PYTHONIOENCODING='utf-8')
    return subprocess.run([sys.executable, *args], cwd=cwd, env=env, capture_output=True,
                          text=True, encoding='utf-8', errors='replace', timeout=600)


def test_labkit_core_work_names_utf8_for_every_text_file():
    done = _run([WORKFLOW])
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    steps = [line for line in done.stdout.splitlines() if line.startswith('steps: ')]
    assert steps == ['steps: pkg create, pkg create cmake, colcon build, '
                     'colcon build --symlink-install, colcon list, source, ros2 run, '
                     'colcon test, colcon test-result, param dump >, param load, bag info, '
                     'interface show, launch, view_frames']


def test_the_check_catches_an_open_without_encoding_in_labkit():
    """The blame is right: an open() without encoding in a labkit file fails the run,
    the same open() outside labkit does not."""
    from labkit.ament import files
    snippet = ("import encoding_workflow as w, tempfile, os; w.install()\n"
               "path = os.path.join(tempfile.mkdtemp(), 'x.txt')\n"
               "exec(compile('open(path, \"w\").close()', {where!r}, 'exec'))\n"
               "print('no error')\n")
    inside = _run(['-c', snippet.format(where=files.__file__)])
    assert inside.returncode != 0
    assert 'EncodingWarning' in inside.stderr and 'labkit' in inside.stderr
    outside = _run(['-c', snippet.format(where=os.path.join(HERE, 'elsewhere.py'))])
    assert outside.returncode == 0, outside.stderr
    assert outside.stdout.strip() == 'no error'
