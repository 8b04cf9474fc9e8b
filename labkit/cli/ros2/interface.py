"""ros2 interface list | show | package | packages | proto (ros2interface)."""
from labkit.cli.ros2._base import add_verbs, message_to_yaml

INSTALL_PREFIX = '/opt/ros/humble'  # where a Humble install keeps its share/ (for error texts)



def _ifc():
    import labkit.interfaces as ifc
    return ifc


def add_arguments(parser, cli_name):
    add_verbs(parser, cli_name, [
        ('list', 'List all interface types available', _list_args, list_),
        ('package', 'Output a list of available interface types within one package',
         _package_args, package),
        ('packages', 'Output a list of packages that provide interfaces', _packages_args,
         packages),
        ('proto', 'Output an interface prototype', _proto_args, proto),
        ('show', 'Output the interface definition', _show_args, show),
    ])


def _visible(full_name):
    # rosidl_runtime_py hides generated helper types (names with '_')
    return '_' not in full_name.split('/')[-1]


def interfaces_by_kind(kind):
    """{package: [Name, ...]} of one kind ('msg', 'srv', 'action')."""
    result = {}
    for full in _ifc().list_interfaces():
        pkg, k, name = full.split('/')
        if k == kind and _visible(full):
            result.setdefault(pkg, []).append(name)
    return result


def _list_args(p):
    p.add_argument('-m', '--only-msgs', action='store_true',
                   help='Print out only the message types')
    p.add_argument('-s', '--only-srvs', action='store_true',
                   help='Print out only the service types')
    p.add_argument('-a', '--only-actions', action='store_true',
                   help='Print out only the action types')


def _print_kind(io, title, kind):
    io.print(f'{title}:')
    found = interfaces_by_kind(kind)
    for pkg in sorted(found):
        for name in sorted(found[pkg]):
            io.print(f'    {pkg}/{kind}/{name}')


def list_(args, io):
    chosen = [(args.only_msgs, 'Messages', 'msg'), (args.only_srvs, 'Services', 'srv'),
              (args.only_actions, 'Actions', 'action')]
    if not any(flag for flag, _, _ in chosen):
        chosen = [(True, t, k) for _, t, k in chosen]
    for flag, title, kind in chosen:
        if flag:
            _print_kind(io, title, kind)


def _package_args(p):
    p.add_argument('package_name', help="Name of the ROS package (e.g. 'example_interfaces')")


def package(args, io):
    try:
        names = _ifc().list_interfaces(args.package_name)
    except LookupError:
        return f"Unknown package '{args.package_name}'"
    for full in names:
        if _visible(full):
            io.print(full)


def _packages_args(p):
    p.add_argument('-m', '--only-msgs', action='count',
                   help='Only list packages that generate messages')
    p.add_argument('-s', '--only-srvs', action='count',
                   help='Only list packages that generate services')
    p.add_argument('-a', '--only-actions', action='count',
                   help='Only list packages that generate actions')


def packages(args, io):
    if args.only_msgs:
        names = interfaces_by_kind('msg')
    elif args.only_srvs:
        names = interfaces_by_kind('srv')
    elif args.only_actions:
        names = interfaces_by_kind('action')
    else:
        names = _ifc().list_packages()
    for name in sorted(names):
        io.print(name)


def _proto_args(p):
    p.add_argument('type', help="Show an interface definition (e.g. "
                                "'example_interfaces/msg/String')")
    p.add_argument('--no-quotes', action='store_true',
                   help='if true output has no outer quotes.')


def proto(args, io):
    ifc = _ifc()
    parts = args.type.split('/')
    try:
        cls = ifc.get_type(args.type if len(parts) == 3 else args.type)
    except (LookupError, ValueError):
        return f"The passed interface type '{args.type}' is invalid"
    if ifc.is_action(cls):
        instance = cls.Goal()
    elif ifc.is_service(cls):
        instance = cls.Request()
    else:
        instance = cls()
    text = message_to_yaml(instance)
    io.print(text if args.no_quotes else '"' + text + '"')


# --------------------------------------------------------------------------- show

def _show_args(p):
    group = p.add_mutually_exclusive_group()
    group.add_argument('--all-comments', default=False, action='store_true',
                       help='Show all comments, including for nested interface definitions')
    group.add_argument('--no-comments', default=False, action='store_true',
                       help='Show no comments or whitespace')
    p.add_argument('type', help="Show an interface definition (e.g. "
                                "'example_interfaces/msg/String'). Passing '-' reads the "
                                "argument from stdin (e.g. 'ros2 topic type /chatter | ros2 "
                                "interface show -').")


def _check_name(identifier):
    """ros2interface's errors for a name it cannot show."""
    parts = identifier.split('/')
    if len(parts) != 3:
        raise ValueError(
            f"Invalid name '{identifier}'. Expected three parts separated by '/'")
    if not all(parts):
        raise ValueError(f"Invalid name '{identifier}'. Must not contain empty parts")
    ifc = _ifc()
    if parts[0] not in ifc.list_packages():
        raise LookupError(f"Unknown package '{parts[0]}'")
    try:
        ifc.get_interface_text(identifier)
    except (LookupError, ValueError):
        raise LookupError("Could not find the interface "
                          f"'{INSTALL_PREFIX}/share/{identifier}.idl'")


def show(args, io):
    if not args.type:
        return 'the passed value is empty'
    try:
        _check_name(args.type)
    except (ValueError, LookupError) as e:
        return str(e)
    from labkit.interfaces.show import interface_show
    io.print(interface_show(args.type, all_comments=args.all_comments,
                            no_comments=args.no_comments), end='')
