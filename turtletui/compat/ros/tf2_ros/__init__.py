from tf2_py import (  # noqa: F401
    BufferCore,
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)

from tf2_ros.buffer import Buffer  # noqa: F401
from tf2_ros.buffer_interface import (  # noqa: F401
    BufferInterface,
    ConvertRegistration,
    NotImplementedException,
    Stamped,
    TransformRegistration,
    TypeException,
    convert,
)
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster  # noqa: F401
from tf2_ros.transform_broadcaster import TransformBroadcaster  # noqa: F401
from tf2_ros.transform_listener import TransformListener  # noqa: F401
