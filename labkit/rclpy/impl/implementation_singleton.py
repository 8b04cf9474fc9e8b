"""rclpy's handle on its C extension; in labkit a small namespace of the pieces code
outside rclpy sometimes reaches for (exception classes, the ClockType enum)."""
import types

from labkit.rclpy._clock_type import ClockType
from labkit.rclpy.exceptions import InvalidHandle, RCLError, UnknownROSArgsError

rclpy_implementation = types.SimpleNamespace(
    ClockType=ClockType, RCLError=RCLError, UnknownROSArgsError=UnknownROSArgsError,
    InvalidHandle=InvalidHandle, RCL_DEFAULT_DOMAIN_ID=0, RMW_DURATION_INFINITE=2**63 - 1,
    rclpy_get_rmw_implementation_identifier=lambda: 'rmw_fastrtps_cpp')
