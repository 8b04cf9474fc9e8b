"""Record the conformance scripts' output on real rclpy (the Jazzy reference venv).

    python tests/conformance/record.py [name ...]

Writes expected/jazzy/<name>.txt (raw reference stdout) and, for a script that has no
expected/<name>.txt yet, a first copy of it. expected/<name>.txt is the Humble truth:
where Humble and Jazzy differ (documented at the top of each script) it is edited by
hand. For a script that already has one, the differences are shown for review.
Reference interpreter: $ROSREF_PYTHON, else .venv-rosref/bin/python (see benchmarks/README.md).
"""
import difflib
import os
import random
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _scripts import EXPECTED, JAZZY, REFSHIM, run, script_args, scripts  # noqa: E402


def reference_python():
    python = os.environ.get('ROSREF_PYTHON', str(Path(__file__).resolve().parents[2] / '.venv-rosref' / 'bin' / 'python'))
    if not Path(python).exists():
        sys.exit(f'no reference interpreter at {python}: set ROSREF_PYTHON')
    return python


def reference_env():
    env = dict(os.environ)
    env.update({
        'ROS_AUTOMATIC_DISCOVERY_RANGE': 'LOCALHOST',  # DDS discovery stays on this host
        'ROS_DOMAIN_ID': str(random.randint(1, 100)),  # no crosstalk with other runs
        'ROS_PYTHON_CHECK_FIELDS': '1',                # Humble's always-on field checks
        'PYTHONPATH': str(REFSHIM),
        'RCUTILS_COLORIZED_OUTPUT': '0',
        'PYTHONUNBUFFERED': '1',
    })
    return env


def canonical_padding(text):
    """Fast CDR leaves padding bytes uninitialised: re-encode each hex line with rosbags,
    which writes zeros, so the expected bytes are deterministic.

    Length: rmw_fastrtps's rmw_serialize returns its size estimate, 4 + the typesupport's
    get_serialized_size() (Humble and Jazzy alike): plain types are rounded up to 4 bytes
    (Bool -> 8), and an empty sequence of 8-byte numbers still counts its alignment
    (JointState with an empty `velocity` -> 8 bytes more than written). The trailing
    bytes past what is written are uninitialised too: zeros in the expected file.
    """
    from rosbags.serde import SerdeError
    from rosbags.typesys import Stores, get_types_from_msg, get_typestore
    store = get_typestore(Stores.ROS2_HUMBLE)
    store.register(get_types_from_msg('bool data', 'std_srvs/msg/SetBool_Request'))
    store.register(get_types_from_msg('bool success\nstring message',
                                      'std_srvs/msg/SetBool_Response'))
    out = []
    for line in text.splitlines():
        m = re.match(r'^(.*) \[(\S+)\]: (\d+) ([0-9a-f]+)$', line)
        if m:
            label, typename, raw = m.group(1), m.group(2), bytes.fromhex(m.group(4))
            rb_name = typename.replace('/srv/', '/msg/')  # rosbags keeps srv parts as msgs
            for cut in range(0, 16):
                try:
                    msg = store.deserialize_cdr(raw[:len(raw) - cut], rb_name)
                    break
                except SerdeError:
                    continue
            fixed = bytes(store.serialize_cdr(msg, rb_name))
            assert len(fixed) <= len(raw), line
            fixed += bytes(len(raw) - len(fixed))
            line = f'{label} [{typename}]: {len(fixed)} {fixed.hex()}'
        out.append(line)
    return '\n'.join(out) + '\n'


def record(path, python, env):
    returncode, stdout, stderr = run([python, str(path), *script_args(path)], path, env, 60)
    if returncode != 0:
        print(f'!! {path.name} exited {returncode}\n{stderr}')
    if path.stem == 'serialization':
        stdout = canonical_padding(stdout)
    JAZZY.mkdir(parents=True, exist_ok=True)
    (JAZZY / f'{path.stem}.txt').write_text(stdout, encoding='utf-8')
    expected = EXPECTED / f'{path.stem}.txt'
    if not expected.exists():
        expected.write_text(stdout, encoding='utf-8')
        print(f'== {path.stem}: new expected file')
        return
    diff = list(difflib.unified_diff(expected.read_text(encoding='utf-8').splitlines(),
                                     stdout.splitlines(), 'expected (Humble)', 'jazzy',
                                     lineterm='', n=0))
    print(f'== {path.stem}: ' + ('same as expected' if not diff else 'differs:'))
    for line in diff:
        print('   ' + line)


def main(names):
    python, env = reference_python(), reference_env()
    for path in scripts():
        if not names or path.stem in names:
            record(path, python, env)


if __name__ == '__main__':
    main(sys.argv[1:])
