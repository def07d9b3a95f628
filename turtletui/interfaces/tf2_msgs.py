"""tf2_msgs/msg: TFMessage, what /tf carries.

Import path in ROS 2: tf2_msgs.msg.
Definitions copied from the ROS 2 interface packages (Apache-2.0);
the text of each definition is what ``ros2 interface show`` prints.
"""

from turtletui.interfaces import geometry_msgs as _geometry_msgs  # noqa: F401  (nested types)
from turtletui.interfaces._message import define_message as _msg

__all__ = [
    'TFMessage',
]

TFMessage = _msg('tf2_msgs/msg/TFMessage', '''\
geometry_msgs/TransformStamped[] transforms
''', globals())
