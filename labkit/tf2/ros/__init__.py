"""`import tf2_ros`: Buffer, TransformListener, the broadcasters and tf2's exceptions."""
from labkit.tf2.core import (ConnectivityException, ExtrapolationException,  # noqa: F401
                             InvalidArgumentException, LookupException, TimeoutException,
                             TransformException)
from .buffer_interface import *  # noqa: F401,F403
from .buffer import *  # noqa: F401,F403
from .transform_listener import *  # noqa: F401,F403
from .transform_broadcaster import *  # noqa: F401,F403
from .static_transform_broadcaster import *  # noqa: F401,F403
