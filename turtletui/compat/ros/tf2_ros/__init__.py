from tf2_py import *  # noqa: F403  (as tf2_ros does: BufferCore and tf2's exceptions)

from tf2_ros.buffer import Buffer  # noqa: F401
from tf2_ros.buffer_client import BufferClient  # noqa: F401
from tf2_ros.buffer_interface import *  # noqa: F403
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster  # noqa: F401
from tf2_ros.transform_broadcaster import TransformBroadcaster  # noqa: F401
from tf2_ros.transform_listener import TransformListener  # noqa: F401
