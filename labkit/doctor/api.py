"""ros2doctor's machinery: checks, reports, and its warning lines.

A check returns a Result (errors, warnings); a report returns a Report (name,
[(item, value)]). Each has a category linking the two (`--report-failed`).
They run in ros2doctor's order: its entry points sorted by name.
"""
import os
import sys

# what ros2doctor prints as `<file>: <line>: UserWarning: <msg>`: the path below the
# package root, not this machine's site-packages (the same on every machine)
_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# where Humble's ros2doctor checks live (apt's ros-humble-ros2doctor, Python 3.10)
HUMBLE_API = '/opt/ros/humble/lib/python3.10/site-packages/ros2doctor/api'
# the environment /opt/ros/humble/setup.bash sets: labkit's underlay counts as sourced
UNDERLAY_DISTRO = 'humble'


def ros_distro():
    """ROS_DISTRO as a terminal that sourced the underlay has it ('' when emptied)."""
    return os.environ.get('ROS_DISTRO', UNDERLAY_DISTRO).strip()


class Report:
    __slots__ = ['name', 'items']

    def __init__(self, name):
        self.name = name
        self.items = []

    def add_to_report(self, item_name, item_info):
        self.items.append((item_name, item_info))


class Result:
    __slots__ = ['error', 'warning']

    def __init__(self):
        self.error = 0
        self.warning = 0

    def add_error(self):
        self.error += 1

    def add_warning(self):
        self.warning += 1


class Doctor:
    """What the checks share: the CLI's node (graph queries) and where warnings go."""

    def __init__(self, node, eprint):
        self.node = node
        self._eprint = eprint

    def warn(self, msg, at=None, _depth=1):
        """Print one warning line. `at` = (module, line) of the ros2doctor code that
        says the same in Humble: the line then names that file, where a Humble
        install has it, as the real one does. labkit's own checks name their file
        below the package root (the same on every machine)."""
        if at is not None:
            module, line = at
            self._eprint(f'{HUMBLE_API}/{module}.py: {line}: UserWarning: {msg}')
            return
        # ros2doctor's custom warning format, located at the caller like stacklevel=2;
        # printed every time (Python's warnings module would show a repeat only once)
        frame = sys._getframe(_depth)
        path = os.path.relpath(frame.f_code.co_filename, _ROOT).replace(os.sep, '/')
        self._eprint(f'{path}: {frame.f_lineno}: UserWarning: {msg}')

    def error(self, msg, at=None):
        self.warn(f'ERROR: {msg}', at=at, _depth=2)

    def topic_names(self, skip_topics=()):
        return [name for name, _ in self.node.get_topic_names_and_types()
                if name not in skip_topics]


def format_report(report):
    """ros2doctor's format_print, as lines: a blank line, the name, aligned items."""
    lines = ['', f'   {report.name}']
    if report.items:
        longest = max(len(name) for name, _ in report.items)
        padding = longest + 4 if longest >= 8 else 8
        lines += ['{:{padding}}: {}'.format(name, value, padding=padding)
                  for name, value in report.items]
    return lines


def run_checks(doctor, checks, include_warnings=False):
    """(failed categories, failed count, total count), like ros2doctor.api.run_checks."""
    failed, fail, total = set(), 0, 0
    for name, check in checks:
        try:
            result = check.check(doctor)
        except Exception:
            doctor.warn(f'Fail to call {name} class functions.')
            continue
        if result.error or (include_warnings and result.warning):
            fail += 1
            failed.add(check.category)
        total += 1
    return failed, fail, total


def generate_reports(doctor, reports, categories=None):
    out = []
    for name, report in reports:
        try:
            made = report.report(doctor)
        except Exception:
            doctor.warn(f'Fail to call {name} class functions.')
            continue
        if not categories or report.category in categories:
            out.append(made)
    return out
