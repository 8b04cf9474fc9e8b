"""`rosdep install | resolve | keys | check | init | update` over bundled key tables.

rosdep reads every package.xml below --from-paths, collects the dependency
keys and maps each to system packages: system keys through rosdistro's
rosdep YAML files (here base.yaml, python.yaml next to this file), ROS
package names through the distribution (humble.yaml: ros-humble-<name>).
Nothing is installed for real: every key labkit can resolve stands for
something labkit already provides, and the output says so instead of
pretending to run apt-get.
"""
import argparse
import os

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
DISTRO = 'humble'
OS_KEY = 'ubuntu'
KEY_TAGS = ('buildtool_depend', 'buildtool_export_depend', 'build_depend',
            'build_export_depend', 'exec_depend', 'depend', 'test_depend', 'doc_depend')
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


def package_keys(paths):
    """[(package name, [keys in manifest order])] for every package.xml below `paths`."""
    from labkit.ament import files, workspace
    import xml.etree.ElementTree as ET
    found = []
    for path in paths:
        for pkg in workspace.discover([files.expand(path)]):
            root = ET.parse(os.path.join(pkg.path, 'package.xml')).getroot()
            keys = []
            for el in root:
                if el.tag in KEY_TAGS and (el.text or '').strip() not in keys:
                    keys.append((el.text or '').strip())
            found.append((pkg.name, keys))
    return found


# ------------------------------------------------------------------ command line

def _parser():
    from labkit.commands import Parser
    p = Parser(prog='rosdep', usage='rosdep [options] <command> <args>',
               description='Commands:\n\n'
                           'rosdep check <stacks-and-packages>...\n'
                           '  check if the dependencies of package(s) have been met.\n\n'
                           'rosdep install <stacks-and-packages>...\n'
                           '  download and install the dependencies of a given package or '
                           'packages.\n\n'
                           'rosdep keys <stacks-and-packages>...\n'
                           '  list the rosdep keys that the packages depend on.\n\n'
                           'rosdep resolve <rosdeps>\n'
                           '  resolve <rosdeps> to system dependencies\n\n'
                           'rosdep init\n'
                           '  initialize rosdep sources in /etc/ros/rosdep.  May require '
                           'sudo.\n\n'
                           'rosdep update\n'
                           '  update the local rosdep database based on the rosdep sources.',
               formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('command', nargs='?', help=argparse.SUPPRESS)
    p.add_argument('names', nargs='*', help=argparse.SUPPRESS)
    p.add_argument('--from-paths', '--from-path', dest='from_paths', action='store_true',
                   help='Affected commands recurse into directories passed as arguments '
                        'and look for packages there.')
    p.add_argument('-i', '--ignore-src', '--ignore-packages-from-source', dest='ignore_src',
                   action='store_true',
                   help='Affected commands ignore rosdep keys that are ROS packages in '
                        'the given paths.')
    p.add_argument('-y', '--default-yes', action='store_true',
                   help='Tell the package manager to default to y or fail when installing')
    p.add_argument('-r', dest='robust', action='store_true',
                   help='Continue installing despite errors.')
    p.add_argument('-s', '--simulate', action='store_true',
                   help='Simulate install')
    p.add_argument('--rosdistro', default=None,
                   help='Explicitly sets the ROS distro to use, overriding the normal '
                        'method of detecting the ROS distro.')
    p.add_argument('-t', '--dependency-types', action='append', default=None,
                   choices=['build', 'buildtool', 'build_export', 'buildtool_export',
                            'exec', 'test', 'doc'])
    return p


def run_command(command):
    """Run one rosdep command line (without `rosdep`); returns a CompletedCommand."""
    import shlex

    from labkit.commands import CompletedCommand, ParserExit, Streams, set_parse_streams
    from labkit.commands import Recorder as _Recorder
    argv = shlex.split(command) if isinstance(command, str) else [str(a) for a in command]
    if argv[:1] == ['rosdep']:
        argv = argv[1:]
    chunks = []
    out, err = _Recorder('stdout', chunks), _Recorder('stderr', chunks)
    io = Streams(out, err)
    set_parse_streams(io)
    parser = _parser()
    try:
        args = parser.parse_intermixed_args(argv)
    except ParserExit as e:
        return CompletedCommand(['rosdep', *argv], e.status, out.getvalue(), err.getvalue(),
                                None, chunks)
    verbs = {'install': install, 'check': check, 'keys': keys_verb, 'resolve': resolve_verb,
             'init': init, 'update': update}
    if args.command is None:
        parser.print_help()
        rc = 0
    elif args.command not in verbs:
        io.eprint(f'Unsupported command {args.command}.')
        rc = 1
    else:
        if args.rosdistro not in (None, DISTRO):
            io.eprint(f'labkit: only the {DISTRO} key tables are bundled')
            rc = 1
        else:
            rc = verbs[args.command](args, io)
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
    pkgs = package_keys(paths)
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
    pkgs = package_keys(args.names if args.from_paths else [])
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
