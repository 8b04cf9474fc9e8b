"""The middleware check: every publisher/subscription pair's QoS must be compatible."""
import re

from labkit.doctor.api import Report, Result


def _pairs(doctor):
    node = doctor.node
    me = (node.get_name(), node.get_namespace())

    def others(endpoints):
        # the doctor's own node is the tool, not the system under examination
        return [e for e in endpoints if (e.node_name, e.node_namespace) != me]

    for topic in doctor.topic_names():
        for pub in others(node.get_publishers_info_by_topic(topic)):
            for sub in others(node.get_subscriptions_info_by_topic(topic)):
                yield topic, pub, sub


def _strip_level(text):
    found = re.search(r'^(?i:warning|error): (.*)', text)
    return found.group(1) if found else text


class QoSCompatibilityCheck:
    category = 'middleware'

    def check(self, doctor):
        from labkit.rclpy.qos import QoSCompatibility, qos_check_compatible
        result = Result()
        for topic, pub, sub in _pairs(doctor):
            compatibility, reason = qos_check_compatible(pub.qos_profile, sub.qos_profile)
            if compatibility == QoSCompatibility.WARNING:
                doctor.warn(f"QoS compatibility warning found on topic '{topic}': "
                            f'{_strip_level(reason)}', at=('qos_compatibility', 47))
                result.add_warning()
            elif compatibility == QoSCompatibility.ERROR:
                doctor.error(f"QoS compatibility error found on topic '{topic}': "
                             f'{_strip_level(reason)}', at=('qos_compatibility', 51))
                result.add_error()
        return result


class QoSCompatibilityReport:
    category = 'middleware'

    def report(self, doctor):
        from labkit.rclpy.qos import QoSCompatibility, qos_check_compatible
        report = Report('QOS COMPATIBILITY LIST')
        for topic, pub, sub in _pairs(doctor):
            compatibility, reason = qos_check_compatible(pub.qos_profile, sub.qos_profile)
            status = 'OK' if compatibility == QoSCompatibility.OK else reason
            for label, value in (('topic [type]', f'{topic} [{pub.topic_type}]'),
                                 ('publisher node', pub.node_name),
                                 ('subscriber node', sub.node_name),
                                 ('compatibility status', status)):
                report.add_to_report(label, value)
        if not report.items:
            report.add_to_report('compatibility status', 'No publisher/subscriber pairs found')
        return report
