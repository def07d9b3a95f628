"""turtlesim: the turtle's messages, services and action.

Import paths in ROS 2: turtlesim.msg, turtlesim.srv, turtlesim.action up to
Jazzy; from Kilted on the same types are turtlesim_msgs.msg / .srv / .action.
Here both names give the *same* class objects (see ``ros_module_members``);
a run imports only the one its ``--distro`` has (turtletui.compat.distro).
Definitions transcribed from ros/ros_tutorials (BSD-3-Clause), byte for byte
(Pose.msg, Spawn.srv and Kill.srv end without a newline); the text of each is
what ``ros2 interface show`` prints.
"""

from turtletui.interfaces import action_msgs as _action_msgs  # noqa: F401  (Impl types)
from turtletui.interfaces import builtin_interfaces as _builtin_interfaces  # noqa: F401
from turtletui.interfaces import unique_identifier_msgs as _uuid_msgs  # noqa: F401
from turtletui.interfaces._message import define_action as _action
from turtletui.interfaces._message import define_message as _msg
from turtletui.interfaces._message import define_service as _srv

__all__ = [
    'Color',
    'Kill',
    'Pose',
    'RotateAbsolute',
    'SetPen',
    'Spawn',
    'TeleportAbsolute',
    'TeleportRelative',
]

Color = _msg('turtlesim/msg/Color', '''\
uint8 r
uint8 g
uint8 b
''', globals())

Pose = _msg('turtlesim/msg/Pose', '''\
float32 x
float32 y
float32 theta

float32 linear_velocity
float32 angular_velocity''', globals())

Spawn = _srv('turtlesim/srv/Spawn', '''\
float32 x
float32 y
float32 theta
string name # Optional.  A unique name will be created and returned if this is empty
---
string name''', globals())

Kill = _srv('turtlesim/srv/Kill', '''\
string name
---''', globals())

SetPen = _srv('turtlesim/srv/SetPen', '''\
uint8 r
uint8 g
uint8 b
uint8 width
uint8 off
---
''', globals())

TeleportAbsolute = _srv('turtlesim/srv/TeleportAbsolute', '''\
float32 x
float32 y
float32 theta
---
''', globals())

TeleportRelative = _srv('turtlesim/srv/TeleportRelative', '''\
float32 linear
float32 angular
---
''', globals())

RotateAbsolute = _action('turtlesim/action/RotateAbsolute', '''\
# The desired heading in radians
float32 theta
---
# The angular displacement in radians to the starting position
float32 delta
---
# The remaining rotation in radians
float32 remaining
''', globals())
