"""The platform check, PLATFORM INFORMATION and ROS 2 INFORMATION.

PLATFORM INFORMATION is this machine as Python's `platform` sees it (the few
machine-specific lines of `ros2 doctor --report`). ROS 2 INFORMATION is the
distribution labkit emulates, as the rosdistro index describes Humble (kept
here: doctor never goes online).
"""
import platform
import sys

from labkit.doctor.api import Report, Result, ros_distro

DISTRO = {
    'distribution name': 'humble',
    'distribution type': 'ros2',
    'distribution status': 'active',
    'release platforms': {'debian': ['bullseye'], 'rhel': ['8'], 'ubuntu': ['jammy']},
}
MIN_PYTHON = (3, 10)


# the ROS 2 distributions of the rosdistro index (Humble's ros2doctor looks the name up there)
KNOWN_DISTROS = ('ardent', 'bouncy', 'crystal', 'dashing', 'eloquent', 'foxy', 'galactic',
                 'humble', 'iron', 'jazzy', 'kilted', 'rolling')


def distro_or_complain(doctor, module, lines):
    """The ROS_DISTRO name, or None after Humble's complaint (ros2doctor's helpers in
    platform.py and package.py): unset/empty is an error, an unknown name a warning."""
    name = ros_distro().lower()
    if not name:
        doctor.error('ROS_DISTRO is not set.', at=(module, lines[0]))
        return None
    if name not in KNOWN_DISTROS:
        doctor.warn(f'Distribution name {name} is not found', at=(module, lines[1]))
        return None
    return name


class PlatformCheck:
    category = 'platform'

    def check(self, doctor):
        result = Result()
        distro = distro_or_complain(doctor, 'platform', (37, 49))
        if distro is None:
            doctor.error('Missing rosdistro info. Unable to check platform.', at=('platform', 69))
            result.add_error()
            return result
        if distro != DISTRO['distribution name']:
            # a sourced ROS of another distribution: labkit still behaves like Humble
            doctor.warn(f'ROS_DISTRO is {distro}, but labkit emulates '
                        f"{DISTRO['distribution name']}.")
            result.add_warning()
        if sys.version_info[:2] < MIN_PYTHON:
            doctor.error(f'Python {platform.python_version()} is too old: labkit needs '
                         f'{".".join(map(str, MIN_PYTHON))} or newer.')
            result.add_error()
        return result


class PlatformReport:
    category = 'platform'

    def report(self, doctor):
        system = platform.system()
        report = Report('PLATFORM INFORMATION')
        report.add_to_report('system', system)
        report.add_to_report('platform info', platform.platform())
        if system == 'Darwin':
            report.add_to_report('mac OS version', platform.mac_ver())
        report.add_to_report('release', platform.release())
        report.add_to_report('processor', platform.processor())
        report.add_to_report('python', f'{platform.python_implementation()} '
                                       f'{platform.python_version()}')
        return report


class RosdistroReport:
    category = 'platform'

    def report(self, doctor):
        report = Report('ROS 2 INFORMATION')
        if distro_or_complain(doctor, 'platform', (37, 49)) is None:
            return report                   # Humble prints the section empty
        for key, value in DISTRO.items():
            report.add_to_report(key, value)
        return report
