from enum import IntEnum


class ClockType(IntEnum):
    """rcl_clock_type_t."""

    UNINITIALIZED = 0
    ROS_TIME = 1
    SYSTEM_TIME = 2
    STEADY_TIME = 3

    # rclpy's ClockType is a pybind11 enum: str() is 'ClockType.ROS_TIME'
    def __str__(self):
        return f'ClockType.{self.name}'


ClockType.__module__ = 'rclpy.clock'      # Humble defines it in rclpy/clock.py
