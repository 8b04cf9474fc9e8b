"""The platform check, PLATFORM INFORMATION and ROS 2 INFORMATION.

PLATFORM INFORMATION is this machine as Python's `platform` sees it (the few
machine-specific lines of `ros2 doctor --report`). ROS 2 INFORMATION is the
distribution labkit emulates, as the rosdistro index describes Humble (kept
here: doctor never goes online).
"""
import os
import platform
import sys

from labkit.doctor.api import Report, Result

DISTRO = {
    'distribution name': 'humble',
    'distribution type': 'ros2',
    'distribution status': 'active',
    'release platforms': {'debian': ['bullseye'], 'rhel': ['8'], 'ubuntu': ['jammy']},
}
MIN_PYTHON = (3, 10)


class PlatformCheck:
    category = 'platform'

    def check(self, doctor):
        result = Result()
        distro = os.environ.get('ROS_DISTRO', '').strip().lower()
        if distro and distro != DISTRO['distribution name']:
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
        for key, value in DISTRO.items():
            report.add_to_report(key, value)
        return report
