"""The network check and NETWORK CONFIGURATION, honestly: labkit's graph lives in one
Python process, so no interface carries ROS traffic; its few servers (widgets, the
3D viewer) bind 127.0.0.1. What can still be wrong is the ROS_DOMAIN_ID setting."""
import os

from labkit.doctor.api import Report, Result

# rmw's limit for a domain id (ports beyond it do not exist)
MAX_DOMAIN_ID = 232


def domain_id_problem():
    """None, or why ROS_DOMAIN_ID is unusable (rcl refuses such a value)."""
    value = os.environ.get('ROS_DOMAIN_ID', '').strip()
    if not value:
        return None
    if not value.isdigit() or int(value) > MAX_DOMAIN_ID:
        return f'ROS_DOMAIN_ID is {value!r}: it must be an integer from 0 to {MAX_DOMAIN_ID}.'
    return None


class NetworkCheck:
    category = 'network'

    def check(self, doctor):
        result = Result()
        problem = domain_id_problem()
        if problem:
            doctor.error(problem)
            result.add_error()
        return result


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
