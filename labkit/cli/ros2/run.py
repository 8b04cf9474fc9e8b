"""ros2 run PKG EXE [ARGS...] (ros2run): a background job in a labkit process."""
import argparse
import shlex

from labkit.cli.ros2._base import CliError
from labkit.commands import CompletedCommand


def add_arguments(parser, cli_name):
    parser.add_argument('--prefix',
                        help='Prefix command, which should go before the executable. Command '
                             'must be wrapped in quotes if it contains spaces (e.g. --prefix '
                             "'gdb -ex run --args').")
    parser.add_argument('--new', action='store_true',
                        help='labkit: start another copy even if this command already runs')
    parser.add_argument('package_name', help='Name of the ROS package')
    parser.add_argument('executable_name', help='Name of the executable')
    parser.add_argument('argv', nargs=argparse.REMAINDER,
                        help='Pass arbitrary arguments to the executable')
    parser.set_defaults(_verb=run, _background=lambda a: True)


def check(package, executable):
    """ros2run's errors, before anything starts."""
    from labkit import executables
    from labkit.cli.ros2.pkg import package_names
    if package not in package_names() and not executables.executables(package):
        raise CliError(f"Package '{package}' not found")
    if executables.lookup(package, executable) is None:
        raise CliError('No executable found')


def run(args, io):
    """Only reached when not started as a job (never, normally)."""
    raise CliError('ros2 run must start a job')


def start_run_job(argv, args):
    from labkit.cli.ros2 import jobs
    extra = [a for a in args.argv]
    if '--new' in extra and '--ros-args' not in extra[:extra.index('--new')]:
        extra.remove('--new')
    command = 'ros2 run ' + ' '.join(shlex.quote(a) for a in
                                     [args.package_name, args.executable_name, *extra])
    new = args.new or len(extra) < len(args.argv)
    result = jobs.start(argv, command, lambda sink: jobs.start_process(
        [args.package_name, args.executable_name, *extra],
        f'{args.package_name}/{args.executable_name}', sink=sink), new=new)
    code = getattr(result, 'returncode', 0)
    process = getattr(result, 'process', None)
    if process is not None and process.running and not process.exit_hooks:
        process.exit_hooks.append(_say_how_it_ended)   # stopped later (Ctrl-C), or ended
    if isinstance(result, CompletedCommand) and code:
        # the program ended at once: ros2 run says how, as ros2run's run_executable does
        line = f'{ROS2RUN_MSG_PREFIX} {exit_description(code)}\n'
        result = CompletedCommand(result.args, code, result.stdout + line, result.stderr,
                                  result.exception, list(result.chunks) + [('stdout', line)])
    return result


ROS2RUN_MSG_PREFIX = '[ros2run]:'


def _say_how_it_ended(returncode):
    """ros2run's run_executable, after its child ended (in the job's own output)."""
    from labkit import process
    if returncode and not process.current().closing:
        print(f'{ROS2RUN_MSG_PREFIX} {exit_description(returncode)}', flush=True)


def exit_description(returncode):
    """A signal's name for a process killed by it (-N), else the exit code."""
    from labkit import oslayer       # Humble's (Linux's) signal numbers and names on every OS
    if returncode < 0 and oslayer.linux_signal_description(-returncode):
        return oslayer.linux_signal_description(-returncode)
    return 'Process exited with failure %d' % returncode
