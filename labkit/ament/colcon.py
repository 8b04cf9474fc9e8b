"""`colcon build` (and `colcon list`) in the current folder, as colcon-core/colcon-ros do it.

`run_command("build --symlink-install")` returns the same CompletedCommand
as labkit.ros2. Packages are found below --base-paths (default: `.`),
ordered by their package.xml dependencies and built into install/<pkg>
(isolated layout), with build/, install/ and log/ laid out like the real
tool's. The printed order is the executor's (`execute()`): independent
packages start together, up to --parallel-workers (2 in virtual time), and
each one's `Finished <<<` comes when its time has passed; the jobs
themselves run one after the other in this process.

Times: in live mode colcon prints measured wall-clock times. In virtual time
mode it prints a deterministic *cost model* instead (build.py's `cost`: a
fixed base per build type plus a share per module, interface, data file),
so a notebook prints the same times on every run and machine; the figures
are of the size a real Humble build shows, not measurements.

`colcon test` / `test-result` live in colcon_test.py (same discovery and selection).
"""
import argparse
import datetime
import os
import time

from labkit import oslayer
from labkit.ament import build, files, workspace

VERBS = ('build', 'list', 'test', 'test-result')


# ------------------------------------------------------------------ output helpers

def format_duration(seconds):
    """colcon's format: 0.41s, 12.3s, 1min 5s, 1h 2min 3s."""
    minutes, secs = divmod(seconds, 60)
    hours, minutes = divmod(minutes, 60)
    if hours or minutes:
        decimals = 0
    elif round(secs, 2) < 9.995:
        decimals = 2
    elif round(secs, 1) < 59.95:
        decimals = 1
    else:
        decimals = 0
    text = f'{secs:.{decimals}f}s'
    if hours:
        return f'{int(hours)}h {int(minutes)}min {text}'
    if minutes:
        return f'{int(minutes)}min {text}'
    return text


def _plural(n, word='package'):
    return f'{n} {word}' + ('' if n == 1 else 's')


class _Clock:
    """Elapsed time since colcon started: measured (live) or the cost model (virtual)."""

    def __init__(self):
        from labkit.graph import world
        self.virtual = world.mode() == 'virtual'
        self.start = time.monotonic()
        self.model = 0.0

    def now(self):
        return self.model if self.virtual else time.monotonic() - self.start

    def add(self, cost):
        self.model += cost


def _timestamp():
    """The log folder's name part: now (live), or the virtual clock's date."""
    from labkit.graph import world
    seconds = world.system_ns() / 1e9
    return datetime.datetime.fromtimestamp(seconds, datetime.timezone.utc).strftime(
        '%Y-%m-%d_%H-%M-%S') if world.mode() == 'virtual' else \
        datetime.datetime.now().strftime('%Y-%m-%d_%H-%M-%S')


# ------------------------------------------------------------------ parser

# `colcon --help` as Humble users see it on Ubuntu 22.04 (Python 3.10's argparse, 80
# columns) with python3-colcon-common-extensions and python3-colcon-mixin from the ROS apt
# repository (colcon-core of the 0.12-0.15 releases). labkit simulates build, list, test and
# test-result; the other verbs are listed because the real tool lists them. Newer
# colcon-core releases quote the defaults in backticks (`./log`, `~/.colcon`).
USAGE = """usage: colcon [-h] [--log-base LOG_BASE] [--log-level LOG_LEVEL]
              {build,extension-points,extensions,graph,info,list,metadata,mixin,test,test-result,version-check}
              ...
"""
HELP = USAGE + """
options:
  -h, --help            show this help message and exit
  --log-base LOG_BASE   The base path for all log directories (default: ./log,
                        to disable: /dev/null)
  --log-level LOG_LEVEL
                        Set log level for the console output, either by
                        numeric or string value (default: warning)

colcon verbs:
  build                 Build a set of packages
  extension-points      List extension points
  extensions            List extensions
  graph                 Generate a visual representation of the dependency graph
  info                  Package information
  list                  List packages, optionally in topological ordering
  metadata              Manage metadata of packages
  mixin                 Manage CLI mixins
  test                  Test a set of packages
  test-result           Show the test results generated when testing a set of
                        packages
  version-check         Compare local package versions with PyPI

  {build,extension-points,extensions,graph,info,list,metadata,mixin,test,test-result,version-check}
                        call `colcon VERB -h` for specific help

Environment variables:
  CMAKE_COMMAND         The full path to the CMake executable
  COLCON_ALL_SHELLS     Flag to enable all shell extensions
  COLCON_COMPLETION_LOGFILE
                        Set the logfile for completion time
  COLCON_DEFAULTS_FILE  Set path to the yaml file containing the default values
                        for the command line arguments (default:
                        $COLCON_HOME/defaults.yaml)
  COLCON_DEFAULT_EXECUTOR
                        Select the default executor extension
  COLCON_DEFAULT_OUTPUT_STYLE
                        Select the default output style extension
  COLCON_EXTENSION_BLOCKLIST
                        Block extensions which should not be used
  COLCON_HOME           Set the configuration directory (default: ~/.colcon)
  COLCON_LOG_LEVEL      Set the log level (debug|10, info|20, warn|30,
                        error|40, critical|50, or any other positive numeric
                        value)
  COLCON_WARNINGS       Set the warnings filter similar to PYTHONWARNINGS
                        except that the module entry is implicitly set to
                        'colcon.*'
  CTEST_COMMAND         The full path to the CTest executable
  POWERSHELL_COMMAND    The full path to the PowerShell executable

For more help and usage tips, see https://colcon.readthedocs.io
"""



def _parser():
    from labkit.commands import Parser
    parser = Parser(prog='colcon', description='colcon is an extensible command line tool '
                    'to build and test multiple software packages.',
                    formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--log-base', default='log')
    parser.add_argument('--log-level', default=None)
    sub = parser.add_subparsers(title='colcon verbs', dest='verb', parser_class=Parser)
    for verb, doc in (('build', 'Build a set of packages'),
                      ('list', 'List packages, optionally in topological ordering'),
                      ('test', 'Test a set of packages'),
                      ('test-result', 'Show the test results generated when testing a set '
                                      'of packages')):
        if verb.startswith('test'):
            from labkit.ament import colcon_test
            colcon_test.add_arguments(sub.add_parser(verb, description=doc, help=doc), verb)
            continue
        p = sub.add_parser(verb, description=doc, help=doc)
        p.add_argument('--base-paths', nargs='*', default=['.'], metavar='PATH',
                       help='The base paths to recursively crawl for packages '
                            '(default: .)')
        p.add_argument('--packages-select', nargs='*', metavar='PKG_NAME',
                       help='Only process a subset of packages')
        p.add_argument('--packages-skip', nargs='*', metavar='PKG_NAME',
                       help='Skip a set of packages')
        p.add_argument('--packages-up-to', nargs='*', metavar='PKG_NAME',
                       help='Only process a subset of packages and their recursive '
                            'dependencies')
        if verb == 'build':
            p.add_argument('--build-base', default='build',
                           help='The base path for all build directories (default: build)')
            p.add_argument('--install-base', default='install',
                           help='The base path for all install prefixes (default: install)')
            p.add_argument('--merge-install', action='store_true',
                           help='Merge all install prefixes into a single location')
            p.add_argument('--symlink-install', action='store_true',
                           help='Use symlinks instead of copying files where possible')
            p.add_argument('--continue-on-error', action='store_true',
                           help='Continue other packages when a package fails to build')
            p.add_argument('--event-handlers', nargs='*', default=[], metavar='name+/-',
                           help='Enable or disable event handlers')
            p.add_argument('--executor', default='parallel',
                           choices=['parallel', 'sequential'])
            p.add_argument('--parallel-workers', type=int, default=None,
                           metavar='NUMBER')     # None: the cores (see workers())
            p.add_argument('--cmake-args', nargs='*', metavar='*',
                           help='Pass arguments to CMake projects')
            p.add_argument('--cmake-target', metavar='CMAKE_TARGET')
            p.add_argument('--ament-cmake-args', nargs='*', metavar='*')
            p.add_argument('--cmake-clean-cache', action='store_true')
            p.add_argument('--allow-overriding', nargs='*', default=[], metavar='PKG_NAME')
        else:
            p.add_argument('--topological-order', '-t', action='store_true')
            p.add_argument('--names-only', '-n', action='store_true')
            p.add_argument('--paths-only', '-p', action='store_true')
    # set after the verbs: argparse derives the verbs' prog from the usage at that time
    parser.usage = USAGE[len('usage: '):].rstrip('\n')
    return parser


# ------------------------------------------------------------------ entry point

def run_command(command):
    """Run one colcon command line (without the leading `colcon`)."""
    from labkit.commands import CompletedCommand, ParserExit, Streams, set_parse_streams
    from labkit.commands import Recorder as _Recorder
    argv = oslayer.split_args(command) if isinstance(command, str) else [str(a) for a in command]
    if argv[:1] == ['colcon']:
        argv = argv[1:]
    chunks = []
    out, err = _Recorder('stdout', chunks), _Recorder('stderr', chunks)
    io = Streams(out, err)
    set_parse_streams(io)
    parser = _parser()
    argv = _protect_passthrough(argv)
    if argv[:1] in (['-h'], ['--help']):
        io.print(HELP, end='')
        return CompletedCommand(['colcon', *argv], 0, out.getvalue(), err.getvalue(), None,
                                chunks)
    try:
        # a path typed back as labkit printed it (/root/... of the sandbox) means that folder
        args = parser.parse_args([files.expand_arg(a) for a in argv])
    except ParserExit as e:
        return CompletedCommand(['colcon', *argv], e.status, out.getvalue(), err.getvalue(),
                                None, chunks)
    if args.verb is None:
        io.print(USAGE)                 # colcon-core print()s format_usage(): a blank line follows
        io.eprint('Error: No verb provided')
        rc = 1
    else:
        clock = _Clock()
        try:
            from labkit.ament import colcon_test
            verb = {'build': build_verb, 'list': list_verb, 'test': colcon_test.test_verb,
                    'test-result': colcon_test.test_result_verb}[args.verb]
            rc = verb(args, io, clock)
        except RuntimeError as e:
            io.eprint(f'[{clock.now():.3f}s] ERROR:colcon:colcon {args.verb}: {e}')
            rc = 1
    return CompletedCommand(['colcon', *argv], rc, out.getvalue(), err.getvalue(), None,
                            chunks)


PASSTHROUGH = ('--cmake-args', '--ament-cmake-args', '--cmake-target', '--pytest-args',
               '--ctest-args')


def _protect_passthrough(argv):
    """`--cmake-args -DBUILD_TESTING=0`: values starting with '-' are not colcon options.

    colcon does the same before argparse sees them (it prefixes such values with a space).
    """
    result, passing = [], False
    for arg in argv:
        if arg in PASSTHROUGH:
            passing = True
            result.append(arg)
        elif passing and arg.startswith('-') and not arg.startswith('--'):
            result.append(' ' + arg)
        else:
            if arg.startswith('--'):
                passing = False
            result.append(arg)
    return result


def _select(args, io, clock, skip_dirs=()):
    warnings = []
    packages = workspace.discover(args.base_paths, skip_dirs, warnings)
    for warning in warnings:
        io.eprint(f'[{clock.now():.3f}s] {warning}')
    message = workspace.duplicates(packages)
    if message:
        raise RuntimeError(message)
    names = {p.name for p in packages}
    selected = set(names)
    for option, values in (('--packages-select', args.packages_select),
                           ('--packages-up-to', args.packages_up_to),
                           ('--packages-skip', args.packages_skip)):
        for name in values or ():
            if name not in names:
                io.eprint(f"[{clock.now():.3f}s] WARNING:colcon.colcon_core.package_selection:"
                          f"ignoring unknown package '{name}' in {option}")
    if args.packages_select is not None:
        selected &= set(args.packages_select)
    if args.packages_up_to is not None:
        selected &= workspace.up_to(packages, args.packages_up_to)
    if args.packages_skip:
        selected -= set(args.packages_skip)
    ordered = workspace.topological_order(packages)
    return ordered, [p for p in ordered if p.name in selected]


def _underlay_packages():
    """[(name, shown path, run dependencies)] of packages in sourced prefixes and /opt/ros."""
    from labkit.ament import files, index
    found = []
    for prefix in index.prefixes():
        for name in index.resources('packages', prefix):
            deps_file = os.path.join(prefix, 'share', 'colcon-core', 'packages', name)
            try:
                with open(deps_file, encoding='utf-8') as f:
                    deps = {d for d in f.read().strip().split(':') if d}
            except OSError:
                deps = set()
            found.append((name, files.display(prefix), deps))
    # the binary install: the `desktop` metapackage depends on every bundled package
    for name in sorted(index.bundled_package_names()):
        found.append((name, index.SHOWN_INSTALL_PREFIX, set()))
    found.append(('desktop', index.SHOWN_INSTALL_PREFIX, index.bundled_package_names()))
    return found


def _override_check(args, selected, install_base, io, clock):
    """colcon-override-check: overriding an underlay package others depend on warns."""
    names = {p.name for p in selected}
    underlay = _underlay_packages()
    reverse = {}
    for name, path, deps in underlay:
        if name in names:
            continue    # being rebuilt: its own dependencies no longer matter
        for dep in deps & names:
            reverse.setdefault(dep, set()).add(name)
    paths = {}
    for name, path, _ in underlay:
        if name in names and path not in paths.get(name, []):
            paths.setdefault(name, []).append(path)
    overriding = sorted(n for n in paths if reverse.get(n) and
                        n not in (args.allow_overriding or []))
    if not overriding:
        return
    io.eprint(
        f'[{clock.now():.3f}s] WARNING:colcon.colcon_core.package_selection:Some selected '
        'packages are already built in one or more underlay workspaces:\n\t' +
        '\n\t'.join(f"'{n}' is in: " + ', '.join(paths[n]) for n in overriding) +
        '\nIf a package in a merged underlay workspace is overridden and it installs headers, '
        'then all packages in the overlay must sort their include directories by workspace '
        'order. Failure to do so may result in build failures or undefined behavior at run '
        'time.\nIf the overridden package is used by another package in any underlay, then '
        'the overriding package in the overlay must be API and ABI compatible or undefined '
        'behavior at run time may occur.\n\nIf you understand the risks and want to override '
        'a package anyways, add the following to the command line:\n\t--allow-overriding ' +
        ' '.join(overriding) + '\n\nThis may be promoted to an error in a future release of '
        'colcon-override-check.')


def list_verb(args, io, clock):
    ordered, selected = _select(args, io, clock)
    if not args.topological_order:
        selected = sorted(selected, key=lambda p: p.name)
    for p in selected:
        path = oslayer.shown_path(os.path.relpath(p.path))     # src/pkg on every OS
        if args.names_only:
            io.print(p.name)
        elif args.paths_only:
            io.print(path)
        else:
            io.print(f'{p.name}\t{path}\t(ros.{p.build_type})')
    return 0


def build_verb(args, io, clock):
    if args.merge_install:
        io.eprint('labkit: --merge-install is not supported; use the default isolated '
                  'install layout')
        return 1
    build_base = os.path.abspath(args.build_base)
    install_base = os.path.abspath(args.install_base)
    log_base = os.path.abspath(args.log_base)
    skip = (build_base, install_base, log_base)
    ordered, selected = _select(args, io, clock, skip)
    _override_check(args, selected, install_base, io, clock)
    direct = '+' in ''.join(h for h in args.event_handlers if h.startswith('console_direct'))

    for base in (build_base, install_base, log_base):
        os.makedirs(base, exist_ok=True)
        _touch(os.path.join(base, 'COLCON_IGNORE'))
    log_dir = _new_log_dir(log_base)

    in_workspace = {p.name for p in ordered}

    def is_installed(name):
        """Install prefix of a package built here (this run or before), or of an underlay."""
        prefix = os.path.join(install_base, name)
        if os.path.isdir(os.path.join(prefix, 'share', name)):
            return prefix
        if name in in_workspace:
            return None     # in this workspace but not built (yet): CMake cannot find it
        from labkit.ament import index
        try:
            return index.package_prefix(name)
        except LookupError:
            return None

    finished, failed, aborted, stderr_pkgs, events = [], [], [], [], []

    def start(pkg):
        io.print(f'Starting >>> {pkg.name}')
        events.append(f'[{clock.now():.6f}] (-) JobStarted: {{\'identifier\': '
                      f'\'{pkg.name}\'}}')
        measured = time.monotonic()
        ctx = build.Context(pkg, build_base, install_base, args.symlink_install,
                            is_installed)
        builder = {'ament_python': build.build_ament_python,
                   'ament_cmake': build.build_ament_cmake,
                   'cmake': build.build_ament_cmake}.get(pkg.build_type)
        if builder is None:
            res = build.BuildResult().fail(
                f"labkit: build type '{pkg.build_type}' of package '{pkg.name}' is not "
                "supported (ament_python, ament_cmake)")
        else:
            try:
                res = builder(ctx)
            except Exception as e:     # a labkit bug: fail this package, say why
                res = build.BuildResult().fail(f'{type(e).__name__}: {e}')
        _write_package_log(log_dir, pkg.name, res)
        # a failed step still took a moment: CMake fails in its configure step (about as
        # long as the cost model's base for a CMake package), setup.py at once
        failed_cost = 1.45 if pkg.build_type in ('ament_cmake', 'cmake') else 0.3
        took = (res.cost or failed_cost) if clock.virtual else time.monotonic() - measured
        return took, res.returncode, res

    def end(pkg, res, took, was_aborted):
        took = format_duration(max(took, 0.0))
        if was_aborted:     # cancelled by another package's failure
            aborted.append(pkg.name)
            io.print(f'Aborted  <<< {pkg.name} [{took}]')
            events.append(f'[{clock.now():.6f}] ({pkg.name}) JobEnded: {{\'identifier\': '
                          f'\'{pkg.name}\', \'rc\': \'SIGINT\'}}')
            return
        for warning in res.warnings:
            io.eprint(f'[{clock.now():.3f}s] {warning}')
        if direct:
            for line in res.stdout:
                io.print(line)
        if res.stderr:
            stderr_pkgs.append(pkg.name)
            if direct:
                for line in res.stderr:
                    io.eprint(line)
            # colcon-output's console_stderr: the package's stderr as one block at its end
            io.eprint(f'--- stderr: {pkg.name}')
            for line in res.stderr:
                io.eprint(line)
            io.eprint('---')
        if res.returncode:
            failed.append((pkg.name, res.returncode))
            io.print(f'Failed   <<< {pkg.name} [{took}, exited with code {res.returncode}]')
        else:
            finished.append(pkg.name)
            io.print(f'Finished <<< {pkg.name} [{took}]')
        events.append(f'[{clock.now():.6f}] ({pkg.name}) JobEnded: {{\'identifier\': '
                      f'\'{pkg.name}\', \'rc\': {res.returncode}}}')

    not_processed = execute(args, ordered, selected, clock, start, end)

    clock.add(0.25)     # discovery, ordering and the summary itself
    _write_install_scripts(install_base, [p for p in ordered if os.path.isdir(
        os.path.join(install_base, p.name))])
    _write_log_summary(log_dir, events)
    io.print('')    # the summary is separated from the previous output
    io.print(f'Summary: {_plural(len(finished))} finished [{format_duration(clock.now())}]')
    if failed:
        io.print(f'  {_plural(len(failed))} failed: ' + ' '.join(sorted(n for n, _ in failed)))
    if aborted:
        io.print(f'  {_plural(len(aborted))} aborted: ' + ' '.join(sorted(aborted)))
    if stderr_pkgs:
        io.print(f'  {_plural(len(stderr_pkgs))} had stderr output: ' +
                 ' '.join(sorted(stderr_pkgs)))
    if not_processed:
        io.print(f'  {_plural(len(not_processed))} not processed')
    return failed[0][1] if failed else 0


# ------------------------------------------------------------------ executors

# The machine the book's virtual time stands for has 2 cores: colcon's default
# --parallel-workers (os.cpu_count()) is 2 there, whatever this computer has.
VIRTUAL_CORES = 2


def workers(args):
    """How many packages may be processed at once (0: no limit), as the executor reads it."""
    if getattr(args, 'executor', 'parallel') == 'sequential':
        return 1
    if args.parallel_workers is not None:
        return args.parallel_workers
    from labkit.graph import world
    return VIRTUAL_CORES if world.mode() == 'virtual' else os.cpu_count() or 1


def execute(args, ordered, selected, clock, start, end, on_error=None):
    """Process the selected packages in the order colcon's executor does; the names not
    processed (blocked by a failure).

    colcon-parallel-executor starts every ready package (all its selected dependencies
    finished), those with more dependents first, up to --parallel-workers at a time, and
    reports each one when it ends; the sequential executor takes them one by one in
    topological order. labkit runs a package's job when it starts (its dependencies are
    done by then) and holds its end back until its duration has passed on a timeline:
    so `Starting >>> b` comes before `Finished <<< a` when both run at once.

    `start(pkg)` runs the job and returns (duration, rc, payload); `end(pkg, payload,
    duration, aborted)` reports it, with clock.now() at its end (virtual time).
    `on_error` (colcon's OnError): 'interrupt' aborts the running jobs and skips the
    pending ones (colcon build's default), 'skip_downstream' skips the failed package's
    dependents (build --continue-on-error), 'continue' goes on (colcon test's default).
    """
    parallel = getattr(args, 'executor', 'parallel') != 'sequential'
    limit = workers(args)
    if on_error is None:
        on_error = 'skip_downstream' if args.continue_on_error else 'interrupt'
    names = {p.name for p in selected}
    all_deps = workspace.recursive_deps(ordered)
    deps = {p.name: all_deps[p.name] & names - {p.name} for p in selected}
    dependents = {n: sum(n in deps[m] for m in names if m != n) for n in names}
    pending = list(selected)
    running = []                # [end time, sequence, pkg, started, duration, rc, payload]
    now, sequence = clock.now(), 0
    blocked = set()
    while pending or running:
        waiting = {p.name for p in pending} | {r[2].name for r in running}
        ready = [p for p in pending if not deps[p.name] & waiting]
        if parallel:
            ready.sort(key=lambda p: -dependents[p.name])     # stable: topological
        for pkg in ready:
            if limit and len(running) >= limit:
                break
            pending.remove(pkg)
            if clock.virtual:
                clock.model = now
            duration, rc, payload = start(pkg)
            running.append([now + duration, sequence, pkg, now, duration, rc, payload])
            sequence += 1
        if not running:
            break
        running.sort(key=lambda r: (r[0], r[1]))
        done = running.pop(0)
        now = done[0]
        if clock.virtual:
            clock.model = now
        end(done[2], done[6], done[4], False)
        if done[5] and on_error != 'continue':
            if on_error == 'interrupt':
                blocked |= {p.name for p in pending}
                pending = []
                for other in running:       # cancelled when the failure is seen
                    end(other[2], other[6], now - other[3], True)
                running = []
            else:
                downstream = {p.name for p in pending if done[2].name in deps[p.name]}
                blocked |= downstream
                pending = [p for p in pending if p.name not in downstream]
    if clock.virtual:
        clock.model = now
    return blocked


# ------------------------------------------------------------------ files colcon leaves

def _touch(path):
    if not os.path.exists(path):
        open(path, 'w', encoding='utf-8').close()


def _new_log_dir(log_base):
    """log/build_<stamp>/ and the latest_build and latest links, as colcon makes them."""
    stamp = _timestamp()
    name = f'build_{stamp}'
    folder = os.path.join(log_base, name)
    n = 1
    while os.path.exists(folder):      # two builds in the same (virtual) second
        n += 1
        name = f'build_{stamp}_{n}'
        folder = os.path.join(log_base, name)
    os.makedirs(folder)
    for link, target in (('latest_build', name), ('latest', 'latest_build')):
        # a copy or a junction where the OS refuses symlinks (Windows without Developer Mode)
        oslayer.replace_link(target, os.path.join(log_base, link), target_is_directory=True)
    return folder


def _write_package_log(log_dir, name, res):
    try:
        _write_logs(log_dir, name, res)
    finally:      # log/latest* as copies (no symlinks on this OS): show the new logs too
        log_base = os.path.dirname(log_dir)
        for link in ('latest_build', 'latest'):
            oslayer.refresh(os.path.join(log_base, link))


def _write_logs(log_dir, name, res):
    folder = os.path.join(log_dir, name)
    os.makedirs(folder, exist_ok=True)
    out = ''.join(line + '\n' for line in res.stdout)
    err = ''.join(line + '\n' for line in res.stderr)
    for fname, text in (('stdout.log', out), ('stderr.log', err),
                        ('stdout_stderr.log', out + err), ('streams.log', out + err),
                        ('command.log', '')):
        with open(os.path.join(folder, fname), 'w', encoding='utf-8') as f:
            f.write(text)


def _write_log_summary(log_dir, events):
    with open(os.path.join(log_dir, 'events.log'), 'w', encoding='utf-8') as f:
        f.write(''.join(e + '\n' for e in events))
    with open(os.path.join(log_dir, 'logger_all.log'), 'w', encoding='utf-8') as f:
        f.write('')


def _write_install_scripts(install_base, packages):
    """install/setup.bash & co (labkit.ament.envscripts); the order comes from the
    packages' share/colcon-core markers, as colcon's own scripts read it."""
    from labkit.ament import envscripts
    envscripts.workspace_scripts(install_base)


def _write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w', encoding='utf-8') as f:
        f.write(text)
