"""labkit's rclpy is Humble's: a Jazzy-only name fails as it fails on Humble
(labkit/ARCHITECTURE.md, "Humble, not Jazzy", lists what was audited)."""
import pytest


@pytest.fixture
def hook():
    from labkit import compat
    was = compat.is_active()
    compat.activate(quiet=True)
    yield
    if not was:
        compat.deactivate()


def test_clock_type_lives_in_rclpy_clock(hook):
    from rclpy.clock import ClockType
    assert str(ClockType.ROS_TIME) == 'ClockType.ROS_TIME'
    with pytest.raises(ImportError):
        import rclpy.clock_type  # noqa: F401  (Jazzy's module)


def test_subscription_has_no_publisher_count(rclpy, msgs):
    node = rclpy.create_node('humble_api')
    sub = node.create_subscription(msgs.String, 'x', lambda m: None, 10)
    with pytest.raises(AttributeError):
        sub.get_publisher_count()       # Jazzy added it
    node.destroy_node()
