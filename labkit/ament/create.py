"""`ros2 pkg create`: make a new package's folder, as ros2pkg does on Humble.

Same arguments, defaults, console output, file tree and file contents. Two
choices differ on purpose, so a notebook gives the same output on every machine:

* the maintainer defaults to `root <root@todo.todo>` (what a fresh ROS 2 Docker
  container gives), instead of the login name and `git config user.email`;
* a path inside the book's sandbox home (`labkit.ament.files`) is printed as the
  `/root/...` path it stands for.

Humble's `pkg create` does not check the package name (catkin_pkg does that
later, when colcon, rosdep or bloom read package.xml: see `manifest.py`); its
only refusals are an existing folder and an ament_python package named `test`.
"""
import argparse
import os
import sys

from labkit.ament import files, licenses, templates

DEFAULT_MAINTAINER = 'root'
BUILD_TYPES = ['cmake', 'ament_cmake', 'ament_python']


def add_arguments(parser):
    """The options of `ros2 pkg create` (argparse), in ros2pkg's order."""
    parser.add_argument('package_name', help='The package name')
    parser.add_argument('--package-format', '--package_format', type=int, default=3,
                        choices=[2, 3], help='The package.xml format.')
    parser.add_argument('--description', default='TODO: Package description',
                        help='The description given in the package.xml')
    parser.add_argument('--license', default='TODO: License declaration',
                        help='The license attached to this package; this can be an arbitrary '
                             'string, but a LICENSE file will only be generated if it is one '
                             "of the supported licenses (pass '?' to get a list)")
    parser.add_argument('--destination-directory', default=os.curdir,
                        help='Directory where to create the package directory')
    parser.add_argument('--build-type', default='ament_cmake', choices=BUILD_TYPES,
                        help='The build type to process the package with')
    parser.add_argument('--dependencies', nargs='+', default=[], help='list of dependencies')
    parser.add_argument('--maintainer-email',
                        help='email address of the maintainer of this package')
    parser.add_argument('--maintainer-name', default=DEFAULT_MAINTAINER,
                        help='name of the maintainer of this package')
    parser.add_argument('--node-name', help='name of the empty executable')
    parser.add_argument('--library-name', help='name of the empty library')


class _Writer:
    """Creates folders and files, announcing each like ros2pkg ("creating ...")."""

    def __init__(self, out):
        self.out = out

    def folder(self, name, base):
        path = os.path.join(base, name)
        print('creating folder', files.display(path), file=self.out)
        os.makedirs(files.expand(path), exist_ok=True)
        return path

    def file(self, directory, name, text):
        path = os.path.join(directory, name)
        print('creating', files.display(path), file=self.out)
        real = files.expand(path)
        os.makedirs(os.path.dirname(real) or '.', exist_ok=True)
        with open(real, 'w', encoding='utf-8') as f:
            f.write(text)
        return path


def run(args, out=None, err=None):
    """Do the work for parsed `args`; returns None, or an error text (exit code 1)."""
    out = out if out is not None else sys.stdout
    err = err if err is not None else sys.stderr
    available = licenses.identifiers()
    if args.license == '?':
        print('Supported licenses:\n%s' % '\n'.join(available), file=out)
        return 0

    name = args.package_name
    maintainer_name = args.maintainer_name
    maintainer_email = args.maintainer_email or maintainer_name + '@todo.todo'

    node_name = args.node_name or None
    library_name = args.library_name or None
    if node_name and node_name == library_name:
        node_name = node_name + '_node'
        print('[WARNING] node name can not be equal to the library name', file=err)
        print('[WARNING] renaming node to %s' % node_name, file=err)

    build_type = args.build_type
    buildtool_depends = []
    if build_type == 'ament_cmake':
        buildtool_depends = ['ament_cmake_ros'] if library_name else ['ament_cmake']
    test_depends = []
    if build_type == 'ament_cmake':
        test_depends = ['ament_lint_auto', 'ament_lint_common']
    if build_type == 'ament_python':
        test_depends = ['ament_copyright', 'ament_flake8', 'ament_pep257', 'python3-pytest']
        if name == 'test':
            # the package's code folder and its tests folder would be the same `test/`
            return ("Aborted since 'ament_python' packages can't be named 'test'. Please "
                    'choose a different package name.')

    destination = args.destination_directory
    package_path = os.path.join(destination, name)
    if os.path.exists(files.expand(package_path)):
        return ('\nAborted!\nThe directory already exists: ' + files.display(package_path) +
                '\nEither remove the directory or choose a different destination directory '
                'or package name')

    deps = list(args.dependencies)
    p = lambda *values: print(*values, file=out)  # noqa: E731
    p('going to create a new package')
    p('package name:', name)
    p('destination directory:', files.display_abspath(destination))
    p('package format:', args.package_format)
    p('version:', '0.0.0')
    p('description:', args.description)
    p('maintainer:', [f'{maintainer_name} <{maintainer_email}>'])
    p('licenses:', [args.license])
    p('build type:', build_type)
    p('dependencies:', deps)
    if node_name:
        p('node_name:', node_name)
    if library_name:
        p('library_name:', library_name)

    w = _Writer(out)
    package_dir = w.folder(name, destination)
    w.file(package_dir, 'package.xml', templates.package_xml(
        package_format=args.package_format, name=name, description=args.description,
        maintainer_name=maintainer_name, maintainer_email=maintainer_email,
        license=args.license, buildtool_depends=buildtool_depends, depends=deps,
        test_depends=test_depends, build_type=build_type))

    if build_type in ('cmake', 'ament_cmake'):
        p('creating source and include folder')
        source_dir = w.folder('src', package_dir)
        include_dir = w.folder(name, package_dir + os.sep + 'include')
        if build_type == 'cmake':
            w.file(package_dir, 'CMakeLists.txt',
                   templates.cmake_lists(name, deps, node_name, library_name))
            w.file(package_dir, name + 'Config.cmake.in',
                   templates.cmake_config_in(name, node_name, library_name))
            w.file(package_dir, name + 'ConfigVersion.cmake.in',
                   templates.cmake_config_version_in(name))
        else:
            w.file(package_dir, 'CMakeLists.txt',
                   templates.ament_cmake_lists(name, deps, node_name, library_name))
        if node_name:
            w.file(source_dir, node_name + '.cpp', templates.cpp_main(name))
        if library_name:
            w.file(include_dir, library_name + '.hpp', templates.cpp_header(name, library_name))
            w.file(source_dir, library_name + '.cpp', templates.cpp_library(name, library_name))
            w.file(include_dir, 'visibility_control.h', templates.visibility_control(name))
    else:
        p('creating source folder')
        source_dir = w.folder(name, package_dir)
        w.file(package_dir, 'setup.py', templates.setup_py(
            name=name, maintainer_name=maintainer_name, maintainer_email=maintainer_email,
            description=args.description, license=args.license, node_name=node_name))
        w.file(package_dir, 'setup.cfg', templates.setup_cfg(name))
        resource_dir = w.folder('resource', package_dir)
        # the empty marker file colcon installs into the ament index
        w.file(resource_dir, name, '')
        w.file(source_dir, '__init__.py', '')
        test_dir = w.folder('test', package_dir)
        w.file(test_dir, 'test_copyright.py', templates.test_copyright())
        w.file(test_dir, 'test_flake8.py', templates.test_flake8())
        w.file(test_dir, 'test_pep257.py', templates.test_pep257())
        if node_name:
            w.file(source_dir, node_name + '.py', templates.python_main(name))
        if library_name:
            library_dir = w.folder(library_name, source_dir)
            w.file(library_dir, '__init__.py', '')

    if args.license in available:
        with open(os.path.join(files.expand(package_dir), 'LICENSE'), 'w',
                  encoding='utf-8') as f:
            f.write(licenses.license_text(args.license))
    else:
        p("\n[WARNING]: Unknown license '%s'.  This has been set in the package.xml, but "
          'no LICENSE file has been created.\nIt is recommended to use one of the ament '
          'license identitifers:\n%s' % (args.license, '\n'.join(available)))
    return None


# ----------------------------------------------------------------------------- entry points

def verb(args, io):
    """`ros2 pkg create` as a labkit CLI verb: main(args, io) (see labkit/cli/ros2/_base.py)."""
    return run(args, out=io.out, err=io.err)


def main(argv):
    """`ros2 pkg create ARGV...` on its own; prints, returns the exit code."""
    parser = argparse.ArgumentParser(prog='ros2 pkg create', description='Create a new ROS 2 package')
    add_arguments(parser)
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:
        return e.code if isinstance(e.code, int) else 2
    result = run(args)
    if isinstance(result, str):
        print(result, file=sys.stderr)
        return 1
    return result or 0
