"""`ros2 doctor` (alias `ros2 wtf`): run the checks, or print the reports."""
from labkit.doctor import network, package, platform, qos_compatibility, rmw, topic
from labkit.doctor.api import Doctor, format_report, generate_reports, run_checks

# ros2doctor's entry points, in the order it loads them (sorted by entry-point name)
CHECKS = [
    ('NetworkCheck', network.NetworkCheck()),
    ('PackageCheck', package.PackageCheck()),
    ('PlatformCheck', platform.PlatformCheck()),
    ('QoSCompatibilityCheck', qos_compatibility.QoSCompatibilityCheck()),
    ('TopicCheck', topic.TopicCheck()),
]
REPORTS = [
    ('NetworkReport', network.NetworkReport()),
    ('PackageReport', package.PackageReport()),
    ('PlatformReport', platform.PlatformReport()),
    ('QoSCompatibilityReport', qos_compatibility.QoSCompatibilityReport()),
    ('RMWReport', rmw.RMWReport()),
    ('RosdistroReport', platform.RosdistroReport()),
    ('TopicReport', topic.TopicReport()),
]


def add_arguments(parser, cli_name):
    group = parser.add_mutually_exclusive_group(required=False)
    group.add_argument('--report', '-r', action='store_true', help='Print all reports.')
    group.add_argument('--report-failed', '-rf', action='store_true',
                       help='Print reports of failed checks only.')
    parser.add_argument('--include-warnings', '-iw', action='store_true',
                        help='Include warnings as failed checks. Warnings are ignored by '
                             'default.')
    parser.set_defaults(_verb=main)


def _print_reports(io, reports):
    for report in reports:
        for line in format_report(report):
            io.print(line)


def main(args, io):
    from labkit.commands import CliNode
    with CliNode() as node:
        doctor = Doctor(node, io.eprint)
        if args.report:
            _print_reports(io, generate_reports(doctor, REPORTS))
            return None
        failed, fail, total = run_checks(doctor, CHECKS, include_warnings=args.include_warnings)
        if fail:
            io.print(f'\n{fail}/{total} check(s) failed\n')
            io.print('Failed modules:', *sorted(failed))
        else:
            io.print(f'\nAll {total} checks passed\n')
        if args.report_failed and fail:
            _print_reports(io, generate_reports(doctor, REPORTS, categories=failed))
    return None
