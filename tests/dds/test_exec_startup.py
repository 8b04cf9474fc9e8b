"""`labkit exec` starts as fast as a real rclpy program (issue 19): an empty script imports
none of labkit's heavy parts (numpy, IPython, the graph view, the HTTP server of a window,
YAML, Cyclone DDS), and DDS is joined as Humble's rmw does it, with the program's first
node (rclpy.init() alone joins nothing), in the background; at exit nothing is left
running, also when the program ends while the join is still under way. (The speed itself
is measured by benchmarks/bench_startup.py, not here.) A latched message published before
the join reaching a real subscriber: tests/dds/test_real_peers.py."""
import subprocess
import sys
import textwrap

from tests.dds.test_real_peers import REPO, _env, domain  # noqa: F401

HEAVY = ('numpy', 'IPython', 'labkit.viz.graph_view', 'http.server', 'yaml', 'cyclonedds',
         'labkit.dds.bridge')

# runs the program as `labkit exec` does, then reports what is still running
WRAPPER = textwrap.dedent('''
    import sys, threading
    from labkit.cli.main import exec_file
    rc = exec_file(sys.argv[1], time_mode='live')
    print('rc', rc, 'threads left', sorted(t.name for t in threading.enumerate()
                                           if t is not threading.main_thread()))
''')


def run(tmp_path, domain, code, dds='on'):
    path = tmp_path / 'prog.py'
    path.write_text(textwrap.dedent(code), encoding='utf-8')
    env = _env(domain, LABKIT_TIME='live', LABKIT_DDS=dds, PYTHONPATH=str(REPO))
    done = subprocess.run([sys.executable, '-c', WRAPPER, str(path)], env=env,
                          capture_output=True, text=True, timeout=60, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    return done.stdout


def loaded():
    return f"[m for m in {HEAVY!r} if m in sys.modules]"


def test_an_empty_program_imports_nothing_heavy_and_joins_nothing(tmp_path, domain):
    out = run(tmp_path, domain, f"""
        import sys
        print('loaded', {loaded()})
    """)
    assert out == "loaded []\nrc 0 threads left []\n"


def test_init_alone_joins_nothing_the_first_node_joins_in_the_background(tmp_path, domain):
    out = run(tmp_path, domain, f"""
        import sys
        import rclpy
        from std_msgs.msg import String
        from labkit import dds
        rclpy.init()
        print('after init: connected', dds.is_connected(), 'loaded', {loaded()})
        node = rclpy.create_node('first')
        node.create_publisher(String, 'chatter', 10).publish(String(data='x'))
        print('published; loaded', [m for m in {loaded()} if not m.startswith(('cyclone', 'labkit.dds'))])
        dds.settle_discovery(0.1, 0.5)       # waits for the join under way
        b = dds.current()
        print('joined', b is not None and b.domain_id == {domain})
        node.destroy_node()
        rclpy.shutdown()
    """)
    assert out == ("after init: connected False loaded []\n"
                   "published; loaded []\n"
                   "joined True\n"
                   "rc 0 threads left []\n"), out


def test_a_program_that_ends_while_joining_leaves_nothing_running(tmp_path, domain):
    out = run(tmp_path, domain, """
        import rclpy
        rclpy.init()
        node = rclpy.create_node('brief')
        print('made')
    """)
    assert out == "made\nrc 0 threads left []\n"


def test_dds_off_never_joins(tmp_path, domain):
    out = run(tmp_path, domain, f"""
        import sys
        import rclpy
        rclpy.init()
        node = rclpy.create_node('local')
        print('loaded', {loaded()})
    """, dds='off')
    assert out == "loaded []\nrc 0 threads left []\n"
