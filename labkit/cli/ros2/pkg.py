"""ros2 pkg executables | list | prefix | xml (ros2pkg) over labkit's package index."""
import os

from labkit.ament import create
from labkit.cli.ros2._base import add_verbs

INSTALL_PREFIX = '/opt/ros/humble'  # the prefix a Humble binary install reports
PACKAGE_NOT_FOUND = 'Package not found'


def add_arguments(parser, cli_name):
    add_verbs(parser, cli_name, [
        ('create', 'Create a new ROS 2 package', create.add_arguments, create.verb),
        ('executables', 'Output a list of package specific executables', _exe_args,
         executables),
        ('list', 'Output a list of available packages', None, list_),
        ('prefix', 'Output the prefix path of a package', _prefix_args, prefix),
        ('xml', 'Output the XML of the package manifest or a specific tag', _xml_args, xml),
    ])


# --------------------------------------------------------------------------- the index

def _ament():
    """labkit.ament (workspaces) when present: it knows prefixes and package.xml files."""
    try:
        import labkit.ament as ament
        return ament
    except ImportError:
        return None


def package_names():
    from labkit import executables as exe
    names = set(exe.packages())
    try:
        import labkit.interfaces as ifc
        names |= set(ifc.list_packages())
    except Exception:
        pass
    ament = _ament()
    if ament is not None and hasattr(ament, 'package_names'):
        names |= set(ament.package_names())
    try:    # packages with only a share folder (urdf_tutorial): labkit's bundled prefixes
        from labkit.ament import index
        names |= index.bundled_package_names()
    except ImportError:
        pass
    return sorted(n for n in names if not n.startswith('_'))


def prefix_of(package):
    """The package's real prefix folder (a workspace's install/<pkg>, or a bundled one)."""
    try:
        from labkit.ament import index
        return index.get_package_prefix(package)
    except ImportError:
        return INSTALL_PREFIX if package in package_names() else None
    except Exception:       # PackageNotFoundError
        return None


def shown(path):
    """A path as a Humble machine prints it (bundled prefixes are /opt/ros/humble)."""
    try:
        from labkit.ament import index
        return index.shown(path)
    except ImportError:
        return path


def executable_names(package):
    from labkit import executables as exe
    return sorted(e for p, e in exe.executables(package))


# --------------------------------------------------------------------------- verbs

def _exe_args(p):
    p.add_argument('package_name', nargs='?', help='The package name')
    p.add_argument('--full-path', action='store_true', default=False,
                   help='Show full path of each executable')


def executables(args, io):
    packages = package_names() if args.package_name is None else [args.package_name]
    for package in packages:
        prefix = prefix_of(package)
        if prefix is None:
            return f"Package '{args.package_name}' not found"
        for name in executable_names(package):
            io.print(shown(os.path.join(prefix, 'lib', package, name)) if args.full_path
                     else f'{package} {name}')


def list_(args, io):
    for name in package_names():
        io.print(name)


def _prefix_args(p):
    p.add_argument('package_name', help='The package name')
    p.add_argument('--share', action='store_true', help='Show share directory for the package')


def prefix(args, io):
    found = prefix_of(args.package_name)
    if found is None:
        return PACKAGE_NOT_FOUND
    io.print(shown(os.path.join(found, 'share', args.package_name) if args.share else found))


def _xml_args(p):
    p.add_argument('package_name', help='The package name')
    p.add_argument('-t', '--tag', help="The XML tag to output (e.g. 'version')")


def xml(args, io):
    import xml.etree.ElementTree as ET
    found = prefix_of(args.package_name)
    if found is None:
        return PACKAGE_NOT_FOUND
    path = os.path.join(found, 'share', args.package_name, 'package.xml')
    # the bundled packages have no manifest; never read a path of this machine for them
    if found == INSTALL_PREFIX or not os.path.isfile(path):
        return 'Package XML manifest not found'
    tree = ET.parse(path)
    if args.tag is None:
        io.print(ET.tostring(tree.getroot(), encoding='unicode'))
        return 0
    elements = tree.getroot().findall(args.tag)
    if not elements:
        return 'XML tag not found'
    for element in elements:
        io.print(element.text)
