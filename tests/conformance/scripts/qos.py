"""Conformance: QoS profiles (defaults, presets, policy enums, short keys, invalid
profiles, compatibility checks).

Plain rclpy: runs unchanged on ROS 2 Humble.
Enums are printed by .name: QoSProfile's str() shows IntEnum members, whose str() differs
between Python 3.10 (Humble's) and 3.11.
Humble/Jazzy: Jazzy adds BEST_AVAILABLE to the reliability, durability and liveliness
policies (short keys, presets); the expected file keeps Humble's.
"""
from rclpy.duration import Duration
from rclpy.qos import (InvalidQoSProfileException, QoSDurabilityPolicy, QoSHistoryPolicy,
                       QoSLivelinessPolicy, QoSPresetProfiles, QoSProfile, QoSReliabilityPolicy,
                       qos_check_compatible, qos_profile_parameter_events,
                       qos_profile_parameters, qos_profile_sensor_data,
                       qos_profile_services_default, qos_profile_system_default)


def describe(label, qos):
    print(f'{label}: history={qos.history.name} depth={qos.depth} '
          f'reliability={qos.reliability.name} durability={qos.durability.name} '
          f'liveliness={qos.liveliness.name} deadline={qos.deadline.nanoseconds} '
          f'lifespan={qos.lifespan.nanoseconds} '
          f'lease={qos.liveliness_lease_duration.nanoseconds} '
          f'avoid_ros_namespace_conventions={qos.avoid_ros_namespace_conventions}')


def attempt(label, fn):
    try:
        value = fn()
        print(f'{label}: ok {value!r}')
    except Exception as e:  # noqa: B902 - the class name and text are what we check
        print(f'{label}: {type(e).__name__}: {e}')


def main():
    describe('QoSProfile(depth=10)', QoSProfile(depth=10))
    describe('KEEP_ALL', QoSProfile(history=QoSHistoryPolicy.KEEP_ALL))
    describe('latched', QoSProfile(depth=1, durability=QoSDurabilityPolicy.TRANSIENT_LOCAL,
                                   reliability=QoSReliabilityPolicy.RELIABLE))
    describe('sensor_data', qos_profile_sensor_data)
    describe('system_default', qos_profile_system_default)
    describe('services_default', qos_profile_services_default)
    describe('parameters', qos_profile_parameters)
    describe('parameter_events', qos_profile_parameter_events)
    describe('int policies', QoSProfile(depth=5, reliability=2, durability=1, history=1))
    attempt('QoSProfile()', lambda: QoSProfile())
    attempt('QoSProfile(history=KEEP_LAST)',
            lambda: QoSProfile(history=QoSHistoryPolicy.KEEP_LAST))
    attempt('QoSProfile(dept=10)', lambda: QoSProfile(dept=10))
    attempt('InvalidQoSProfileException base',
            lambda: InvalidQoSProfileException.__mro__[1].__name__)

    for policy in (QoSHistoryPolicy, QoSReliabilityPolicy, QoSDurabilityPolicy,
                   QoSLivelinessPolicy):
        print(policy.__name__, [(m.name, int(m)) for m in policy], policy.short_keys())
    print('short key lookups:', QoSReliabilityPolicy.get_from_short_key('best_effort'),
          QoSDurabilityPolicy.get_from_short_key('TRANSIENT_LOCAL'),
          QoSReliabilityPolicy.RELIABLE.short_key)
    print('presets:', QoSPresetProfiles.short_keys())
    describe('preset sensor_data', QoSPresetProfiles.get_from_short_key('sensor_data'))

    a = QoSProfile(depth=10)
    b = QoSProfile(depth=10)
    print('equal:', a == b, a == QoSProfile(depth=5), a == 'x')
    a.depth = 3
    a.deadline = Duration(seconds=1)
    print('assigned:', a.depth, a.deadline.nanoseconds)

    reliable = QoSProfile(depth=10)
    best_effort = QoSProfile(depth=10, reliability=QoSReliabilityPolicy.BEST_EFFORT)
    latched = QoSProfile(depth=10, durability=QoSDurabilityPolicy.TRANSIENT_LOCAL)
    for label, pub, sub in (('reliable -> reliable', reliable, reliable),
                            ('best effort -> reliable', best_effort, reliable),
                            ('reliable -> best effort', reliable, best_effort),
                            ('volatile -> transient local', reliable, latched),
                            ('transient local -> volatile', latched, reliable)):
        compatibility, reason = qos_check_compatible(pub, sub)
        print(f'compatible {label}:', compatibility.name, repr(reason))
    print('done')


if __name__ == '__main__':
    main()
