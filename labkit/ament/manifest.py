"""package.xml: read it and check it the way catkin_pkg does.

catkin_pkg is the library colcon, rosdep and bloom use to read package.xml;
its `Package.validate()` is where ROS enforces the package-name rule (which
`ros2 pkg create` itself does not check). Same rules, same texts.
"""
import os
import re
import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

NAME_ALLOWED = r'^[a-zA-Z0-9][a-zA-Z0-9_-]*$'   # accepted (upper case, dashes: legacy)
NAME_CONVENTION = r'^[a-z][a-z0-9_-]*$'         # recommended
VERSION = r'^[0-9]+\.[0-9]+\.[0-9]+$'
EMAIL = r'^[-a-zA-Z0-9_%+]+(\.[-a-zA-Z0-9_%+]+)*@[-a-zA-Z0-9%]+(\.[-a-zA-Z0-9%]+)*\.[a-zA-Z]{2,}$'


class InvalidPackage(Exception):
    """catkin_pkg's error: "Error(s) in package '<path>':" then one line per problem."""

    def __init__(self, msg, package_path=None):
        super().__init__(msg)
        self.msg = msg
        self.package_path = package_path

    def __str__(self):
        head = "Error(s) in package '%s':\n" % self.package_path if self.package_path else ''
        return head + self.msg


@dataclass
class Package:
    name: str
    version: str = ''
    description: str = ''
    package_format: int = 1
    maintainers: list = field(default_factory=list)   # [(name, email)]
    licenses: list = field(default_factory=list)
    depends: dict = field(default_factory=dict)       # tag -> [names]
    build_type: str = 'catkin'
    filename: str | None = None

    def validate(self, warnings=None):
        """Raise InvalidPackage on errors; warnings go to `warnings` or stderr ("WARNING: ")."""
        errors, new_warnings = [], []
        if not self.name:
            errors.append('Package name must not be empty')
        if not re.match(NAME_ALLOWED, self.name):
            errors.append('Package name "%s" does not follow naming conventions' % self.name)
        elif not re.match(NAME_CONVENTION, self.name):
            new_warnings.append(
                'Package name "%s" does not follow the naming conventions. It should start with '
                'a lower case letter and only contain lower case letters, digits, underscores, '
                'and dashes.' % self.name)
        if not self.version:
            errors.append('Package version must not be empty')
        elif not re.match(VERSION, self.version):
            errors.append('Package version "%s" does not follow version conventions'
                          % self.version)
        if not self.description:
            errors.append('Package description must not be empty')
        if not self.maintainers:
            errors.append("Package '{0}' must declare at least one maintainer".format(self.name))
        for person, email in self.maintainers:
            if email and not re.match(EMAIL, email):
                errors.append('Invalid email "%s" for person "%s"' % (email, person))
            if not email:
                errors.append('Maintainers must have an email address')
        if not self.licenses:
            errors.append('The package node must contain at least one "license" tag')
        for tag, names in self.depends.items():
            if self.name in names:
                # catkin_pkg reports <depend> as the build_depend it expands to
                label = 'build_depend' if tag == 'depend' else tag
                errors.append('The package "%s" must not "%s" on a package with the same name '
                              'as this package' % (self.name, label))
        for warning in new_warnings:
            if warnings is None:
                print('WARNING: ' + warning, file=sys.stderr)
            elif warning not in warnings:
                warnings.append(warning)
        if errors:
            raise InvalidPackage('\n'.join(errors), self.filename)


_DEPEND_TAGS = ('buildtool_depend', 'build_depend', 'build_export_depend', 'exec_depend',
                'depend', 'test_depend', 'doc_depend')


def parse_package(path):
    """Read `path` (a package folder or its package.xml) into a Package (not validated)."""
    from labkit.ament import files
    path = files.expand(path)
    filename = os.path.join(path, 'package.xml') if os.path.isdir(path) else path
    root = ET.parse(filename).getroot()

    def text(tag):
        el = root.find(tag)
        return (el.text or '').strip() if el is not None else ''

    export = root.find('export')
    build_type = 'catkin'
    if export is not None and export.find('build_type') is not None:
        build_type = (export.find('build_type').text or '').strip()
    return Package(
        name=text('name'), version=text('version'), description=text('description'),
        package_format=int(root.get('format', '1')),
        maintainers=[((m.text or '').strip(), m.get('email')) for m in root.findall('maintainer')],
        licenses=[(el.text or '').strip() for el in root.findall('license')],
        depends={t: [(el.text or '').strip() for el in root.findall(t)]
                 for t in _DEPEND_TAGS if root.findall(t)},
        build_type=build_type, filename=files.display(filename))
