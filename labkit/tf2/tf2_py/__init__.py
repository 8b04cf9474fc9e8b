"""`import tf2_py`: BufferCore and tf2's exceptions."""
from labkit.tf2.core import (BufferCore, ConnectivityException,  # noqa: F401
                             ExtrapolationException, InvalidArgumentException, LookupException,
                             TimeoutException, TransformException)
