"""The topic check and TOPIC LIST: publishers without subscribers and the reverse."""
from labkit.doctor.api import Report, Result

SKIP_TOPICS = ['/parameter_events', '/rosout']


class TopicCheck:
    category = 'topic'

    def check(self, doctor):
        result = Result()
        node = doctor.node
        for topic in doctor.topic_names(skip_topics=SKIP_TOPICS):
            pub_count = node.count_publishers(topic)
            sub_count = node.count_subscribers(topic)
            if pub_count > 0 and sub_count == 0:
                doctor.warn(f'Publisher without subscriber detected on {topic}.', at=('topic', 42))
                result.add_warning()
            elif sub_count > 0 and pub_count == 0:
                doctor.warn(f'Subscriber without publisher detected on {topic}.', at=('topic', 45))
                result.add_warning()
        return result


class TopicReport:
    category = 'topic'

    def report(self, doctor):
        report = Report('TOPIC LIST')
        topics = doctor.topic_names(skip_topics=SKIP_TOPICS)
        if not topics:
            report.add_to_report('topic', 'none')
            report.add_to_report('publisher count', 0)
            report.add_to_report('subscriber count', 0)
        for topic in topics:
            report.add_to_report('topic', topic)
            report.add_to_report('publisher count', doctor.node.count_publishers(topic))
            report.add_to_report('subscriber count', doctor.node.count_subscribers(topic))
        return report
