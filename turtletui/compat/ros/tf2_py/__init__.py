from turtletui.compat.tf2.buffer_core import BufferCore  # noqa: F401
from turtletui.compat.tf2.exceptions import (  # noqa: F401
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)
