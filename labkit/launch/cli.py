"""`ros2 launch <package> <file> [name:=value ...]` and `ros2 launch <path>` (ros2launch).

Registered as a ros2 noun by labkit.ament. The launch runs as a background
job (its own labkit process); each node is a further process.
"""
import os


def add_arguments(parser, cli_name):
    parser.add_argument('-n', '--noninteractive', default=True, action='store_true',
                        help='Run the launch system non-interactively, with no terminal '
                             'associated')
    parser.add_argument('-d', '--debug', default=False, action='store_true',
                        help='Put the launch system in debug mode, provides more verbose '
                             'output.')
    group = parser.add_mutually_exclusive_group()
    group.add_argument('-p', '--print', '--print-description', default=False,
                       action='store_true',
                       help='Print the launch description to the console without launching '
                            'it.')
    group.add_argument('-s', '--show-args', '--show-arguments', default=False,
                       action='store_true',
                       help='Show arguments that may be given to the launch file.')
    parser.add_argument('-a', '--show-all-subprocesses-output', default=False,
                        action='store_true',
                        help="Show all launched subprocesses' output by overriding their "
                             'output configuration using the OVERRIDE_LAUNCH_PROCESS_OUTPUT '
                             'envvar.')
    parser.add_argument('--launch-prefix', help='Prefix command, which should go before all '
                        'executables.')
    parser.add_argument('package_name',
                        help='Name of the ROS package which contains the launch file')
    parser.add_argument('launch_file_name', nargs='?', help='Name of the launch file')
    parser.add_argument('launch_arguments', nargs='*',
                        help="Arguments to the launch file; '<name>:=<value>' (for "
                             'duplicates, last one wins)')
    parser.set_defaults(_verb=main, _background=lambda a: not (a.print or a.show_args))


def find_launch_file(package_name, file_name):
    """ros2launch: the one file of that name below the package's share directory."""
    from labkit.ament.index import get_package_share_directory
    share = get_package_share_directory(package_name)
    matches = []
    for root, dirs, files in os.walk(share):
        dirs.sort()
        if file_name in files:
            matches.append(os.path.join(root, file_name))
    if not matches:
        raise FileNotFoundError(
            "file '{}' was not found in the share directory of package '{}' which is at '{}'"
            .format(file_name, package_name, _shown(share)))
    if len(matches) > 1:
        raise RuntimeError(
            "file '{}' was found more than once in the share directory of package '{}': [{}]"
            .format(file_name, package_name, ', '.join("'{}'".format(_shown(m))
                                                       for m in matches)))
    return matches[0]


def _shown(path):
    from labkit.ament import index
    return index.shown(path)


def parse_launch_arguments(arguments):
    parsed = []
    for argument in arguments:
        name, sep, value = argument.partition(':=')
        if not sep or not name:
            raise RuntimeError("malformed launch argument '{}', expected format "
                               "'<name>:=<value>'".format(argument))
        parsed.append((name, value))
    return parsed


def main(args, io):
    from labkit import compat
    from labkit.ament.index import PackageNotFoundError
    compat.activate(quiet=True)
    launch_arguments = []
    if os.path.isfile(args.package_name):
        path = args.package_name
        if args.launch_file_name is not None:
            launch_arguments.append(args.launch_file_name)
    elif os.path.exists(args.package_name):
        return 'No launch file supplied'      # a folder given instead of a file
    else:
        try:
            path = find_launch_file(args.package_name, str(args.launch_file_name))
        except PackageNotFoundError as e:
            return "Package '{}' not found: {}".format(args.package_name, e)
        except (FileNotFoundError, RuntimeError) as e:
            return str(e)
    launch_arguments += args.launch_arguments
    parsed = parse_launch_arguments(launch_arguments)
    if args.show_args:
        return show_arguments(path, io)
    if args.print:
        from labkit.launch.launch_description_sources import \
            get_launch_description_from_any_launch_file
        description = get_launch_description_from_any_launch_file(path)
        io.print(describe(description))
        return 0
    return launch_file(path, parsed)


def launch_file(path, launch_arguments):
    """Run a launch file to its end (or Ctrl-C); returns the exit code."""
    from labkit.launch import LaunchDescription, LaunchService
    from labkit.launch.actions import IncludeLaunchDescription
    from labkit.launch.launch_description_sources import AnyLaunchDescriptionSource
    service = LaunchService(argv=[f'{n}:={v}' for n, v in launch_arguments])
    service.include_launch_description(LaunchDescription([
        IncludeLaunchDescription(AnyLaunchDescriptionSource(path),
                                 launch_arguments=launch_arguments)]))
    return service.run()


def show_arguments(path, io):
    from labkit.launch.launch_description_sources import \
        get_launch_description_from_any_launch_file
    description = get_launch_description_from_any_launch_file(path)
    io.print("Arguments (pass arguments as '<name>:=<value>'):")
    arguments = description.get_launch_arguments()
    conditional = False
    for arg in arguments:
        text = "\n    '" + arg.name + "':"
        if arg._conditionally_included:
            conditional = True
            text += '*'
        text += '\n        ' + arg.description
        if arg.default_value is not None:
            text += '\n        (default: {})'.format(_shown(
                ' + '.join(token.describe() for token in arg.default_value)))
        io.print(text)
    if arguments:
        if conditional:
            io.print('\n* argument(s) which are only used if specific conditions occur')
    else:
        io.print('\n  No arguments.')
    return 0


def describe(description, indent=''):
    lines = [f'{indent}<launch.launch_description.LaunchDescription>']
    for entity in description.entities:
        lines.append(f'{indent}├── {type(entity).__name__}')
    return '\n'.join(lines)
