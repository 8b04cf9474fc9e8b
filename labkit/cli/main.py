"""The `labkit` console command.

    labkit exec [--time live|virtual] FILE [ARGS...]   run a ROS 2 Python program on labkit
    labkit ros2 VERB ...                                 run a ros2 verb (interface show, ...)
    labkit lab [--root DIR] [JUPYTERLAB OPTIONS...]      the book in JupyterLab, live time
    labkit teacher collect FOLDER [--out DIR]             re-run learners' exercises: CSV + HTML
"""
import argparse
import os
import runpy
import sys


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    from labkit.viz import window    # a simulator started from a terminal opens its window
    window.ENABLED = True
    parser = argparse.ArgumentParser(
        prog='labkit', description='Run ROS 2 Python programs and ros2 verbs on labkit.')
    commands = parser.add_subparsers(dest='command', metavar='{exec,ros2,lab,teacher}')
    p_exec = commands.add_parser('exec', help='run FILE as __main__ with rclpy = labkit')
    p_exec.add_argument('--time', choices=('live', 'virtual'), default='live',
                        help='time mode (default: live, like a real ROS 2 process)')
    p_exec.add_argument('file', metavar='FILE')
    p_exec.add_argument('args', nargs=argparse.REMAINDER, metavar='ARGS')
    p_ros2 = commands.add_parser('ros2', help='run a ros2 verb', add_help=False)
    p_ros2.add_argument('args', nargs=argparse.REMAINDER)
    commands.add_parser('lab', help='open the book in JupyterLab (live time)', add_help=False)
    commands.add_parser('teacher', help="a class's grades and domains (collect, domain)",
                        add_help=False)
    # argparse would eat the script's own options: split at FILE ourselves.
    if argv[:1] == ['ros2']:
        return ros2_main(argv[1:])
    if argv[:1] == ['lab']:
        from labkit.tools import lab
        return lab.main(argv[1:])
    if argv[:1] == ['teacher']:
        from labkit.teacher.__main__ import main as teacher
        return teacher(argv[1:])
    args = parser.parse_args(argv)
    if args.command == 'exec':
        return exec_file(args.file, args.args, time_mode=args.time)
    parser.print_help()
    return 0


def set_time_mode(mode):
    """Choose live/virtual before the world clock starts."""
    os.environ['LABKIT_TIME'] = mode
    from labkit.graph import world
    world.set_mode(mode)


def exec_file(path, args=(), *, time_mode=None):
    """Run a Python file as `python FILE ARGS...` would, with the import hook active.

    `time_mode` ('live' for the console command) is set before the program
    starts; None keeps the current one. Returns the exit code python would give.
    """
    if not os.path.exists(path):
        print(f"labkit: can't open file '{path}': [Errno 2] No such file or directory",
              file=sys.stderr)
        return 2
    if time_mode is not None:
        set_time_mode(time_mode)
    if not _join_dds(deferred=True):
        return 1
    from labkit import compat
    was_active = compat.is_active()
    compat.activate()
    old_argv, old_path0 = sys.argv, sys.path[0] if sys.path else None
    sys.argv = [path, *args]
    sys.path.insert(0, os.path.dirname(os.path.abspath(path)))
    try:
        runpy.run_path(path, run_name='__main__')
        rc = 0
    except SystemExit as e:
        rc = _exit_code(e.code)
    except KeyboardInterrupt:
        _print_user_traceback(path)
        rc = 130
    except BaseException:
        _print_user_traceback(path)
        rc = 1
    finally:
        sys.argv = old_argv
        if sys.path and sys.path[0] != old_path0:
            del sys.path[0]
        _stop_everything()
        if not was_active:
            compat.deactivate()
    return rc


def _join_dds(settle=False, deferred=False):
    """Like a ROS 2 process, join the DDS graph (live time, unless LABKIT_DDS=off).
    False after a one-line error that ROS would also stop on (a bad ROS_DOMAIN_ID).

    deferred (labkit exec): as Humble's rmw, the participant comes with the program's
    first node, and is made in the background while the program goes on."""
    from labkit import dds
    if not dds.auto_enabled():
        return True
    try:
        if deferred:
            dds.join_at_first_node()
            return True
        dds.connect()
    except dds.ConfigError as e:
        if os.environ.get('ROS_DOMAIN_ID', '').strip().isdigit():
            # a domain DDS cannot map to ports: the program runs until its first node,
            # which ends it with Fast DDS's line, as on Humble (labkit.rclpy.node)
            return True
        print(f"labkit: {e}", file=sys.stderr)
        return False
    except Exception as e:   # no DDS here: keep working in-process, say so once
        print(f"[WARN] [labkit.dds]: {e}; staying in-process", file=sys.stderr)
        return True
    if settle:
        dds.settle_discovery()
    return True


# nouns whose verbs look at or join the graph (others, like `interface`, stay offline)
_GRAPH_NOUNS = {'node', 'topic', 'service', 'action', 'param', 'run', 'launch', 'bag',
                'lifecycle', 'component'}


def _exit_code(code):
    if code is None:
        return 0
    if isinstance(code, int):
        return code
    print(code, file=sys.stderr)
    return 1


def _print_user_traceback(path):
    """Print the traceback as python would: without labkit's and runpy's own frames."""
    etype, value, tb = sys.exc_info()
    target = os.path.abspath(path)
    while tb is not None and os.path.abspath(tb.tb_frame.f_code.co_filename) != target:
        tb = tb.tb_next
    from labkit.process import python_traceback   # as Humble's python3.10 prints it
    sys.stderr.write(python_traceback(value.with_traceback(tb)))


def _stop_everything():
    """A finished program leaves nothing running (threads would keep the interpreter alive)."""
    try:
        import labkit
        labkit.reset()
    except Exception:
        pass


def ros2_main(argv):
    if argv[:1] and argv[0] in _GRAPH_NOUNS:
        # a program (run, launch) joins with its first node, like `labkit exec`; a verb
        # that looks at the graph joins now and lets discovery settle first
        starts = argv[0] in ('run', 'launch')
        if not _join_dds(settle=not starts, deferred=starts):
            return 1
    try:
        return _ros2_verb(argv)
    finally:   # leave DDS politely: peers drop our nodes now, not at lease expiry
        if 'labkit.dds' in sys.modules:
            sys.modules['labkit.dds'].disconnect()


def _ros2_verb(argv):
    from labkit.cli.ros2 import run_command
    result = run_command(list(argv))
    if getattr(result, 'wait', None) is not None and result.returncode is None:
        # a long-running verb: follow it until Ctrl-C, like a terminal
        try:
            result.wait()
        except KeyboardInterrupt:
            result.stop()
        return 0
    from labkit.cli.magics import emit
    emit(result)
    return result.returncode or 0
