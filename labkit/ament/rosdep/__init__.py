"""`rosdep install | resolve | keys | check | init | update` over bundled key tables.

rosdep reads every package.xml below --from-paths, collects the dependency
keys and maps each to system packages: system keys through rosdistro's
rosdep YAML files (here base.yaml, python.yaml next to this file), ROS
package names through the distribution (humble.yaml: ros-humble-<name>).
Nothing is installed for real: every key labkit can resolve stands for
something labkit already provides, and the output says so instead of
pretending to run apt-get.
"""
import optparse
import os
import types

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
DISTRO = 'humble'
OS_KEY = 'ubuntu'
VERSION = '0.25.1'
SUCCESS = '#All required rosdeps installed successfully'
UNRESOLVED = ('ERROR: the following packages/stacks could not have their rosdep keys resolved\n'
              'to system dependencies:')

_tables = None


def tables():
    """(system key -> [apt packages], set of ROS package names)."""
    global _tables
    if _tables is None:
        rules = {}
        for name in ('base.yaml', 'python.yaml'):
            with open(os.path.join(HERE, name), encoding='utf-8') as f:
                for key, value in (yaml.safe_load(f) or {}).items():
                    packages = (value or {}).get(OS_KEY)
                    if isinstance(packages, list):
                        rules[key] = ('apt', packages)
                    elif isinstance(packages, dict) and 'pip' in packages:
                        rules[key] = ('pip', packages['pip'].get('packages', []))
        with open(os.path.join(HERE, f'{DISTRO}.yaml'), encoding='utf-8') as f:
            ros = set(yaml.safe_load(f).get('packages', []))
        _tables = (rules, ros)
    return _tables


def resolve(key):
    """('apt', [packages]) or None, like `rosdep resolve <key>`."""
    rules, ros = tables()
    if key in rules:
        return rules[key]
    if key in ros:
        return ('apt', ['ros-%s-%s' % (DISTRO, key.replace('_', '-'))])
    return None


# which dependency types each package.xml tag stands for (catkin_pkg's format 3 reading:
# <depend> is build + build_export + exec)
TAG_TYPES = {
    'buildtool_depend': ('buildtool',), 'buildtool_export_depend': ('buildtool_export',),
    'build_depend': ('build',), 'build_export_depend': ('build_export',),
    'exec_depend': ('exec',), 'depend': ('build', 'build_export', 'exec'),
    'test_depend': ('test',), 'doc_depend': ('doc',),
}
DEFAULT_TYPES = ('build', 'buildtool', 'build_export', 'buildtool_export', 'exec', 'test')


def package_keys(paths, types=None):
    """[(package name, [keys in manifest order])] for every package.xml below `paths`.

    `types` (rosdep's -t): the dependency types to include; all but doc by default."""
    from labkit.ament import files, workspace
    import xml.etree.ElementTree as ET
    wanted = set(types or DEFAULT_TYPES)
    found = []
    for path in paths:
        for pkg in workspace.discover([files.expand(path)]):
            root = ET.parse(os.path.join(pkg.path, 'package.xml')).getroot()
            keys = []
            for el in root:
                key = (el.text or '').strip()
                if wanted.intersection(TAG_TYPES.get(el.tag, ())) and key not in keys:
                    keys.append(key)
            found.append((pkg.name, keys))
    return found


# ------------------------------------------------------------------ command line

# The help of rosdep 0.22.0-0.25.1 (what Humble users got from the ROS apt repository
# 2022-2024). rosdep parses with optparse, so the help is the whole usage text (with the
# Commands list) and then "Options:". Differences from newer releases, written down:
# 0.26 adds a `rosdep search` command to this list. The `-t` help prints a Python set,
# whose order changes from run to run on a real machine; labkit prints one fixed order.
_COMMANDS = """rosdep [options] <command> <args>

Commands:

rosdep check <stacks-and-packages>...
  check if the dependencies of package(s) have been met.

rosdep install <stacks-and-packages>...
  download and install the dependencies of a given package or packages.

rosdep db
  generate the dependency database and print it to the console.

rosdep init
  initialize rosdep sources in /etc/ros/rosdep.  May require sudo.

rosdep keys <stacks-and-packages>...
  list the rosdep keys that the packages depend on.

rosdep resolve <rosdeps>
  resolve <rosdeps> to system dependencies

rosdep update
  update the local rosdep database based on the rosdep sources.

rosdep what-needs <rosdeps>...
  print a list of packages that declare a rosdep on (at least
  one of) <rosdeps>

rosdep where-defined <rosdeps>...
  print a list of yaml files that declare a rosdep on (at least
  one of) <rosdeps>

rosdep fix-permissions
  Recursively change the permissions of the user's ros home directory.
  May require sudo.  Can be useful to fix permissions after calling
  "rosdep update" with sudo accidentally.
"""
DEPENDENCY_TYPES = ('exec', 'test', 'buildtool', 'doc', 'buildtool_export', 'build',
                    'build_export')


class _OptionParser(optparse.OptionParser):
    """optparse that writes into the command's streams and never calls sys.exit."""

    def __init__(self, io):
        self.io = io
        super().__init__(usage=_COMMANDS, prog='rosdep',
                         formatter=optparse.IndentedHelpFormatter(width=78))

    def print_usage(self, file=None):
        self.io.err.write(self.get_usage())

    def print_help(self, file=None):
        self.io.out.write(self.format_help())

    def exit(self, status=0, msg=None):
        if msg:
            self.io.err.write(msg)
        raise _Exit(status)


class _Exit(Exception):
    def __init__(self, status):
        super().__init__(status)
        self.status = status


def _parser(io):
    from labkit.ament import files
    cache = files.display(files.expand('~/.ros/rosdep/sources.cache'))
    p = _OptionParser(io)
    add = p.add_option
    add('--os', dest='os_override', metavar='OS_NAME:OS_VERSION',
        help='Override OS name and version (colon-separated), e.g. ubuntu:lucid')
    add('-c', '--sources-cache-dir', dest='sources_cache_dir', metavar='SOURCES_CACHE_DIR',
        help='Override ' + cache)
    flags = (
        (('--verbose', '-v'), 'verbose', 'verbose display'),
        (('--version',), 'print_version', 'print just the rosdep version, then exit'),
        (('--all-versions',), 'print_all_versions',
         'print rosdep version and version of installers, then exit'),
        (('--reinstall',), 'reinstall', '(re)install all dependencies, even if already installed'),
        (('--default-yes', '-y'), 'default_yes',
         'Tell the package manager to default to y or fail when installing'),
        (('--simulate', '-s'), 'simulate', 'Simulate install'),
        (('-r',), 'robust', 'Continue installing despite errors.'),
        (('-q',), 'quiet', 'Quiet. Suppress output except for errors.'),
        (('-a', '--all'), 'rosdep_all', 'select all packages'),
    )
    for names, dest, text in flags:
        add(*names, dest=dest, action='store_true', default=False, help=text)
    add('-n', dest='recursive', default=True, action='store_false',
        help="Do not consider implicit/recursive dependencies.  Only valid with 'keys', "
             "'check', and 'install' commands.")
    add('--ignore-packages-from-source', '--ignore-src', '-i', dest='ignore_src',
        action='store_true', default=False,
        help="Affects the 'check', 'install', and 'keys' verbs. If specified then rosdep "
             "will ignore keys that are found to be catkin or ament packages anywhere in "
             "the ROS_PACKAGE_PATH, AMENT_PREFIX_PATH or in any of the directories given "
             "by the --from-paths option.")
    add('--skip-keys', dest='skip_keys', action='append', default=[],
        help="Affects the 'check' and 'install' verbs. The specified rosdep keys will be "
             "ignored, i.e. not resolved and not installed. The option can be supplied "
             "multiple times. A space separated list of rosdep keys can also be passed as "
             "a string. A more permanent solution to locally ignore a rosdep key is "
             "creating a local rosdep rule with an empty list of packages (include it in "
             "/etc/ros/rosdep/sources.list.d/ before the defaults).")
    add('--filter-for-installers', action='append', default=[],
        help="Affects the 'db' verb. If supplied, the output of the 'db' command is "
             "filtered to only list packages whose installer is in the provided list. The "
             "option can be supplied multiple times. A space separated list of installers "
             "can also be passed as a string. Example: "
             "`--filter-for-installers \"apt pip\"`")
    add('--from-paths', dest='from_paths', action='store_true', default=False,
        help="Affects the 'check', 'keys', and 'install' verbs. If specified the arguments "
             "to those verbs will be considered paths to be searched, acting on all catkin "
             "packages found there in.")
    add('--rosdistro', dest='rosdistro', default=None, metavar='ROS_DISTRO',
        help="Explicitly sets the ROS distro to use, overriding the normal method of "
             "detecting the ROS distro using the ROS_DISTRO environment variable. When "
             "used with the 'update' verb, only the specified distro will be updated.")
    add('--as-root', default=[], action='append', metavar='INSTALLER_KEY:<bool>',
        help="Override whether sudo is used for a specific installer, e.g. '--as-root "
             "pip:false' or '--as-root \"pip:no homebrew:yes\"'. Can be specified "
             "multiple times.")
    add('--include-eol-distros', dest='include_eol_distros', action='store_true',
        default=False,
        help="Affects the 'update' verb. If specified end-of-life distros are being "
             "fetched too.")
    add('-t', '--dependency-types', dest='dependency_types', type='choice',
        choices=list(DEPENDENCY_TYPES), default=[], action='append',
        help='Dependency types to install, can be given multiple times. Choose from '
             '{%s}. Default: all except doc.' % ', '.join(repr(t) for t in DEPENDENCY_TYPES))
    return p


def run_command(command):
    """Run one rosdep command line (without `rosdep`); returns a CompletedCommand."""
    from labkit import oslayer
    from labkit.commands import CompletedCommand, Streams
    from labkit.commands import Recorder as _Recorder
    argv = oslayer.split_args(command) if isinstance(command, str) else [str(a) for a in command]
    if argv[:1] == ['rosdep']:
        argv = argv[1:]
    chunks = []
    out, err = _Recorder('stdout', chunks), _Recorder('stderr', chunks)
    io = Streams(out, err)
    parser = _parser(io)
    try:
        options, rest = parser.parse_args(argv)
    except _Exit as e:
        return CompletedCommand(['rosdep', *argv], e.status, out.getvalue(), err.getvalue(),
                                None, chunks)
    args = types.SimpleNamespace(**vars(options), command=rest[0] if rest else None,
                                 names=rest[1:])
    verbs = {'install': install, 'check': check, 'keys': keys_verb, 'resolve': resolve_verb,
             'init': init, 'update': update}
    known = ('check', 'db', 'install', 'init', 'keys', 'resolve', 'update', 'what-needs',
             'what_needs', 'where-defined', 'where_defined', 'fix-permissions')
    try:
        if args.print_version or args.print_all_versions:
            io.print(VERSION)
            rc = 0
        elif args.command is None:
            parser.error('Please enter a command')
        elif args.command not in known:
            parser.error(f'Unsupported command {args.command}.')
        elif args.command not in verbs:
            io.eprint(f'labkit: rosdep {args.command} is not simulated (labkit has check, '
                      'install, keys, resolve, init, update)')
            rc = 1
        elif args.rosdistro not in (None, DISTRO):
            io.eprint(f'labkit: only the {DISTRO} key tables are bundled')
            rc = 1
        else:
            rc = verbs[args.command](args, io)
    except _Exit as e:
        rc = e.status
    return CompletedCommand(['rosdep', *argv], rc, out.getvalue(), err.getvalue(), None,
                            chunks)


def _collect(args, io):
    """(resolved [(pkg, key, (installer, [packages]))], unresolved [(pkg, key)])."""
    if not args.from_paths:
        # named packages: look them up in the sourced workspaces' package.xml files
        from labkit.ament import index
        paths = []
        for name in args.names:
            try:
                paths.append(os.path.join(index.get_package_share_directory(name)))
            except KeyError:
                io.eprint(f'ERROR: Rosdep cannot find all required resources to answer '
                          f'your query\nMissing resource {name}')
                return None
    else:
        paths = args.names
    pkgs = package_keys(paths, args.dependency_types)
    local = {name for name, _ in pkgs}
    resolved, unresolved = [], []
    for name, keys in pkgs:
        for key in keys:
            if args.ignore_src and key in local:
                continue
            rule = resolve(key)
            if rule is None:
                unresolved.append((name, key))
            else:
                resolved.append((name, key, rule))
    return resolved, unresolved


def _report_unresolved(unresolved, io):
    io.eprint(UNRESOLVED)
    seen = set()
    for pkg, key in unresolved:
        if (pkg, key) not in seen:
            seen.add((pkg, key))
            io.eprint(f'{pkg}: Cannot locate rosdep definition for [{key}]')


def install(args, io):
    collected = _collect(args, io)
    if collected is None:
        return 1
    resolved, unresolved = collected
    if unresolved:
        _report_unresolved(unresolved, io)
        if not args.robust:
            return 1
        io.eprint('Continuing to install resolvable dependencies...')
    packages = []
    for _, _, (installer, names) in resolved:
        for n in names:
            if (installer, n) not in packages:
                packages.append((installer, n))
    if packages:
        # honest: nothing is installed, everything listed is part of labkit already
        io.print('labkit: these system packages are already provided by labkit '
                 '(nothing to install):')
        for installer, name in packages:
            io.print(f'#[{installer}] {name}')
    io.print(SUCCESS)
    return 0


def check(args, io):
    collected = _collect(args, io)
    if collected is None:
        return 1
    resolved, unresolved = collected
    if unresolved:
        _report_unresolved(unresolved, io)
        return 1
    io.print('All system dependencies have been satisfied')
    return 0


def keys_verb(args, io):
    pkgs = package_keys(args.names if args.from_paths else [], args.dependency_types)
    local = {n for n, _ in pkgs}
    for name, keys in pkgs:
        for key in keys:
            if not (args.ignore_src and key in local):
                io.print(key)
    return 0


def resolve_verb(args, io):
    if not args.names:
        io.eprint('rosdep: error: no rosdep keys given')
        return 1
    for key in args.names:
        rule = resolve(key)
        if rule is None:
            io.eprint(f'ERROR: no rosdep rule for \'{key}\'')
            return 1
        installer, names = rule
        io.print(f'#{installer}')
        io.print(' '.join(names))
    return 0


def init(args, io):
    io.print('labkit: rosdep init would write /etc/ros/rosdep/sources.list.d/20-default.list '
             '(the list of key tables to download); labkit bundles its key tables, so '
             'there is nothing to initialise.')
    return 0


def update(args, io):
    io.print('labkit: rosdep update would download the rosdistro key tables (base.yaml, '
             'python.yaml, the humble distribution); labkit works offline with the tables '
             'bundled in labkit/ament/rosdep/, so nothing was downloaded.')
    return 0
