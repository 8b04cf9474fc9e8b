"""The network check and NETWORK CONFIGURATION, honestly: labkit's graph lives in one
Python process, so no interface carries ROS traffic; its few servers (widgets, the
3D viewer) bind 127.0.0.1. Humble's check looks at the machine's interfaces (loopback,
multicast); it does not look at ROS_DOMAIN_ID, and neither does this one: a bad domain
id makes rcl refuse to start a node, not ros2doctor complain."""
import os

from labkit.doctor.api import Report, Result


class NetworkCheck:
    category = 'network'

    def check(self, doctor):
        return Result()         # nothing of the machine's network is in play


class NetworkReport:
    category = 'network'

    def report(self, doctor):
        report = Report('NETWORK CONFIGURATION')
        report.add_to_report('inet', '127.0.0.1')
        report.add_to_report('inet4', ['127.0.0.1'])
        report.add_to_report('netmask', '255.0.0.0')
        report.add_to_report('device', 'loopback only')
        report.add_to_report('transport', 'in-process (no ROS traffic leaves this Python process)')
        report.add_to_report('domain id', os.environ.get('ROS_DOMAIN_ID', '').strip() or '0')
        return report
