"""The package check and PACKAGE VERSIONS: labkit and the Python packages it needs.

ros2doctor compares local ROS packages with the rosdistro's latest releases
(online). labkit's "packages" are its Python dependencies: the check says
whether each installed version meets labkit's requirement, offline.
"""
from importlib import metadata

from labkit.doctor.api import Report, Result

DISTRIBUTION = 'labkit'


def requirements():
    """[(distribution name, specifier text)] that labkit declares."""
    from packaging.requirements import Requirement
    out = []
    for text in metadata.requires(DISTRIBUTION) or []:
        req = Requirement(text)
        if req.marker is None or req.marker.evaluate():
            out.append((req.name, req.specifier))
    return out


def local_version(name):
    try:
        return metadata.version(name)
    except metadata.PackageNotFoundError:
        return None


class PackageCheck:
    category = 'package'

    def check(self, doctor):
        from labkit.doctor.platform import distro_or_complain
        result = Result()
        if distro_or_complain(doctor, 'package', (40, 52)) is None:
            # Humble compares with the distribution's release versions: none to compare with
            doctor.error('distro packages info is not found.', at=('package', 150))
            result.add_error()
            return result
        try:
            wanted = requirements()
        except metadata.PackageNotFoundError:
            doctor.error('local package info is not found.')
            result.add_error()
            return result
        for name, spec in wanted:
            have = local_version(name)
            if have is None:
                doctor.error(f'{name} is not installed (labkit needs {name}{spec}).')
                result.add_error()
            elif spec and not spec.contains(have, prereleases=True):
                doctor.warn(f'{name} does not meet labkit\'s requirement. '
                            f'local: {have}, required: {spec}')
                result.add_warning()
        return result


class PackageReport:
    category = 'package'

    def report(self, doctor):
        from labkit.doctor.platform import distro_or_complain
        report = Report('PACKAGE VERSIONS')
        if distro_or_complain(doctor, 'package', (40, 52)) is None:
            return report                   # Humble prints the section empty
        report.add_to_report(DISTRIBUTION, f'local={local_version(DISTRIBUTION)}')
        try:
            wanted = requirements()
        except metadata.PackageNotFoundError:
            return report
        for name, spec in sorted(wanted, key=lambda r: r[0].lower()):
            have = local_version(name) or 'not installed'
            report.add_to_report(name, f'local={have}, required: {spec or "any"}')
        return report
