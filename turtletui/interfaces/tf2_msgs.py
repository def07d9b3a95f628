"""tf2_msgs: TFMessage (what /tf carries), TF2Error and tf2's service and action.

Import paths in ROS 2: tf2_msgs.msg, tf2_msgs.srv, tf2_msgs.action.
Definitions copied from the ROS 2 interface packages (Apache-2.0) by
scripts/interfaces_from_ros.py: the text of each is its file's, byte for byte.
"""

from turtletui.interfaces import action_msgs as _action_msgs  # noqa: F401  (nested types)
from turtletui.interfaces import builtin_interfaces as _builtin_interfaces  # noqa: F401  (nested types)
from turtletui.interfaces import geometry_msgs as _geometry_msgs  # noqa: F401  (nested types)
from turtletui.interfaces import unique_identifier_msgs as _unique_identifier_msgs  # noqa: F401  (nested types)
from turtletui.interfaces._message import define_action as _action
from turtletui.interfaces._message import define_message as _msg
from turtletui.interfaces._message import define_service as _srv

__all__ = [
    'FrameGraph',
    'LookupTransform',
    'TF2Error',
    'TFMessage',
]

TF2Error = _msg('tf2_msgs/msg/TF2Error', '''\
uint8 NO_ERROR = 0
uint8 LOOKUP_ERROR = 1
uint8 CONNECTIVITY_ERROR = 2
uint8 EXTRAPOLATION_ERROR = 3
uint8 INVALID_ARGUMENT_ERROR = 4
uint8 TIMEOUT_ERROR = 5
uint8 TRANSFORM_ERROR = 6

uint8 error
string error_string
''', globals())

TFMessage = _msg('tf2_msgs/msg/TFMessage', '''\
geometry_msgs/TransformStamped[] transforms
''', globals())

FrameGraph = _srv('tf2_msgs/srv/FrameGraph', '''\
---
string frame_yaml
''', globals())

LookupTransform = _action('tf2_msgs/action/LookupTransform', '''\
#Simple API
string target_frame
string source_frame
builtin_interfaces/Time source_time
builtin_interfaces/Duration timeout

#Advanced API
builtin_interfaces/Time target_time
string fixed_frame

#Whether or not to use the advanced API
bool advanced

---
geometry_msgs/TransformStamped transform
tf2_msgs/TF2Error error
---
''', globals())
