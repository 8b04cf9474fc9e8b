"""Finding packages in a workspace: discovery, package.xml facts, topological order.

What colcon does before it builds anything (colcon-core's discovery,
package selection and topological_order, colcon-ros' package.xml reading).
"""
import os
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

from labkit import oslayer

IGNORE_MARKERS = ('COLCON_IGNORE', 'AMENT_IGNORE', 'CATKIN_IGNORE')
BUILD_DEPS = ('buildtool_depend', 'build_depend', 'depend', 'build_export_depend')
RUN_DEPS = ('exec_depend', 'depend', 'build_export_depend', 'buildtool_export_depend')
TEST_DEPS = ('test_depend',)


@dataclass
class PackageInfo:
    name: str
    path: str                       # folder, absolute
    build_type: str = 'ament_cmake'
    version: str = '0.0.0'
    deps: dict = field(default_factory=dict)          # category -> set of names
    groups: list = field(default_factory=list)        # member_of_group

    def all_deps(self):
        return set().union(*self.deps.values()) if self.deps else set()


def read_package(folder):
    root = ET.parse(os.path.join(folder, 'package.xml')).getroot()

    def texts(tag):
        return [(el.text or '').strip() for el in root.findall(tag) if (el.text or '').strip()]

    export = root.find('export')
    build_type = 'ament_cmake'      # colcon-ros' default for format 2/3 manifests
    if export is not None and export.find('build_type') is not None:
        build_type = (export.find('build_type').text or '').strip()
    name = (texts('name') or [os.path.basename(folder)])[0]
    deps = {
        'build': {d for t in BUILD_DEPS for d in texts(t)},
        'run': {d for t in RUN_DEPS for d in texts(t)},
        'test': {d for t in TEST_DEPS for d in texts(t)},
    }
    return PackageInfo(name=name, path=os.path.abspath(folder), build_type=build_type,
                       version=(texts('version') or ['0.0.0'])[0], deps=deps,
                       groups=texts('member_of_group'))


def check_manifest(folder):
    """catkin_pkg's complaint about a package.xml (invalid XML, failed checks), or None."""
    from labkit.ament import manifest
    path = os.path.join(folder, 'package.xml')
    shown = oslayer.shown_path(os.path.relpath(path))      # src/pkg/package.xml on every OS
    try:
        ET.parse(path)
    except ET.ParseError as e:
        return "Error(s) in package '%s':\nThe manifest contains invalid XML:\n%s" % (
            shown, e)
    try:
        pkg = manifest.parse_package(folder)
        pkg.filename = shown
        pkg.validate(warnings=[])
    except manifest.InvalidPackage as e:
        e.package_path = shown
        return str(e)
    except Exception as e:     # a manifest catkin_pkg cannot read at all
        return "Error(s) in package '%s':\n%s" % (shown, e)
    return None


def discover(base_paths, skip_dirs=(), warnings=None):
    """Every folder holding a package.xml below the base paths (not below a package).

    A manifest that fails catkin_pkg's checks is left out, with colcon's warning
    appended to `warnings`.
    """
    found = []
    skip = {os.path.abspath(d) for d in skip_dirs}
    for base in base_paths:
        for root, dirs, files in os.walk(os.path.abspath(base)):
            dirs.sort()
            if root in skip or any(m in files for m in IGNORE_MARKERS):
                dirs[:] = []
                continue
            if 'package.xml' in files:
                problem = check_manifest(root)
                if problem is None:
                    found.append(read_package(root))
                elif warnings is not None:
                    warnings.append(
                        'WARNING:colcon.colcon_core.package_identification:Failed to parse '
                        "ROS package manifest in '%s': %s" % (oslayer.shown_path(os.path.relpath(root)),
                                                               problem))
                dirs[:] = []
                continue
            dirs[:] = [d for d in dirs if not d.startswith('.') and d != '__pycache__']
    return found


def duplicates(packages):
    paths = {}
    for p in packages:
        paths.setdefault(p.name, []).append(p.path)
    dup = {n: sorted(v) for n, v in paths.items() if len(v) > 1}
    if not dup:
        return None
    return 'Duplicate package names not supported:\n' + '\n'.join(
        '- ' + name + ':\n' + '\n'.join(f'  - {p}' for p in dup[name]) for name in sorted(dup))


def recursive_deps(packages):
    """name -> every workspace package it depends on, directly or not."""
    by_name = {p.name: p for p in packages}
    direct = {p.name: {d for d in p.all_deps() if d in by_name and d != p.name}
              for p in packages}
    result = {}
    for name in direct:
        seen, todo = set(), list(direct[name])
        while todo:
            d = todo.pop()
            if d not in seen:
                seen.add(d)
                todo.extend(direct.get(d, ()))
        result[name] = seen - {name} if name not in seen else seen
    return result


def topological_order(packages):
    """colcon's order: waves of ready packages, alphabetical within a wave."""
    rec = recursive_deps(packages)
    queued = {p.name: set(rec[p.name]) for p in packages}
    by_name = {p.name: p for p in packages}
    ordered = []
    while queued:
        done = {p.name for p in ordered}
        for q in queued.values():
            q.difference_update(done)
        ready = sorted(n for n, r in queued.items() if not r)
        if not ready:
            lines = sorted('%s: %s' % (n, sorted(r)) for n, r in queued.items())
            raise RuntimeError('Unable to order packages topologically:\n' + '\n'.join(lines))
        for n in ready:
            ordered.append(by_name[n])
            queued.pop(n)
    return ordered


def up_to(packages, names):
    """The named packages and everything they need."""
    rec = recursive_deps(packages)
    wanted = set()
    for n in names:
        if n in rec:
            wanted.add(n)
            wanted |= rec[n]
    return wanted
