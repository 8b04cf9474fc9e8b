"""A tiny in-process stand-in for Gazebo Transport (what `ign topic` talks to).

Gazebo's topics are not ROS topics: `ros2 topic list` does not see them until
ros_gz_bridge republishes them. So the simulator publishes here, and only the
bridge crosses over to the ROS graph. Messages are plain dicts shaped like the
ignition.msgs protobufs (field names as in the .proto files).
"""
import threading


class _Topic:
    def __init__(self, name, msg_type):
        self.name = name
        self.msg_type = msg_type
        self.publishers = 0
        self.subscribers = []          # (callback, msg_type)


class Transport:
    def __init__(self):
        self._lock = threading.Lock()
        self._topics = {}

    def _topic(self, name, msg_type):
        topic = self._topics.get(name)
        if topic is None:
            topic = self._topics[name] = _Topic(name, msg_type)
        return topic

    def advertise(self, name, msg_type):
        """Announce a topic; returns a publish(msg) function."""
        with self._lock:
            topic = self._topic(name, msg_type)
            topic.publishers += 1

        def publish(msg):
            for callback, wanted in list(topic.subscribers):
                if wanted == topic.msg_type:     # gz drops a type mismatch silently
                    callback(msg)
        publish.topic = topic
        return publish

    def unadvertise(self, publish):
        with self._lock:
            topic = publish.topic
            topic.publishers -= 1
            self._forget(topic)

    def subscribe(self, name, msg_type, callback):
        """Call callback(msg) for each message on `name`; returns a handle for unsubscribe."""
        with self._lock:
            topic = self._topic(name, msg_type)
            entry = (callback, msg_type)
            topic.subscribers.append(entry)
        return (topic, entry)

    def unsubscribe(self, handle):
        topic, entry = handle
        with self._lock:
            if entry in topic.subscribers:
                topic.subscribers.remove(entry)
            self._forget(topic)

    def _forget(self, topic):
        if topic.publishers <= 0 and not topic.subscribers:
            self._topics.pop(topic.name, None)

    def has_subscribers(self, name):
        topic = self._topics.get(name)
        return bool(topic and topic.subscribers)

    def topics(self):
        """Sorted names, as `ign topic -l` lists them: topics someone advertises.
        gz-transport's discovery knows publishers only, so a topic that is merely
        subscribed (DiffDrive's cmd_vel before a bridge publishes to it) is not listed."""
        with self._lock:
            return sorted(name for name, topic in self._topics.items() if topic.publishers > 0)

    def info(self, name):
        """(type, publishers, subscribers) or None."""
        topic = self._topics.get(name)
        if topic is None:
            return None
        return topic.msg_type, topic.publishers, len(topic.subscribers)

    def clear(self):
        with self._lock:
            self._topics.clear()


TRANSPORT = Transport()


def normalize_type(name):
    """'gz.msgs.Twist' and 'ignition.msgs.Twist' are the same message (Fortress accepts both)."""
    for prefix in ("gz.msgs.", "ignition.msgs.", "ign.msgs."):
        if name.startswith(prefix):
            return "ignition.msgs." + name[len(prefix):]
    return name


def stamp(sim_time):
    """ignition.msgs.Time of a time in seconds."""
    sec = int(sim_time)
    return {"sec": sec, "nsec": int(round((sim_time - sec) * 1e9))}


def header(sim_time, **data):
    return {"stamp": stamp(sim_time),
            "data": [{"key": key, "value": [value]} for key, value in data.items()]}
