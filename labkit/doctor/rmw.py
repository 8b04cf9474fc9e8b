"""RMW MIDDLEWARE: what carries messages here (labkit's own graph, not a DDS)."""
from labkit.doctor.api import Report

MIDDLEWARE_NAME = 'labkit in-process graph'


class RMWReport:
    category = 'middleware'

    def report(self, doctor):
        report = Report('RMW MIDDLEWARE')
        report.add_to_report('middleware name', MIDDLEWARE_NAME)
        return report
