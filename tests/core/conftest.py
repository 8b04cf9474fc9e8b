import pytest

import labkit
from labkit.graph import world


@pytest.fixture
def virtual():
    """A clean graph in virtual time, clock at the epoch."""
    labkit.reset()
    world.set_mode('virtual')
    yield world
    labkit.reset()


@pytest.fixture
def live():
    labkit.reset()
    world.set_mode('live')
    yield world
    labkit.reset()
    world.set_mode('virtual')


@pytest.fixture
def rclpy(virtual):
    """labkit's rclpy, initialised in the main process."""
    import labkit.rclpy as rclpy
    rclpy.init(args=[])
    yield rclpy
    rclpy.try_shutdown()


@pytest.fixture
def msgs():
    from labkit.interfaces import get_type

    class M:
        String = get_type('std_msgs/msg/String')
        Int32 = get_type('std_msgs/msg/Int32')
        AddTwoInts = get_type('example_interfaces/srv/AddTwoInts')
        Image = get_type('sensor_msgs/msg/Image')
        Log = get_type('rcl_interfaces/msg/Log')
        Clock = get_type('rosgraph_msgs/msg/Clock')
    return M
