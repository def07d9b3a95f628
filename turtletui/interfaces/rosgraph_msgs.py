"""rosgraph_msgs: Clock, what /clock carries when a node uses simulated time.

Import path in ROS 2: rosgraph_msgs.msg.
Definitions copied from the ROS 2 interface packages (Apache-2.0) by
scripts/interfaces_from_ros.py: the text of each is its file's, byte for byte.
"""

from turtletui.interfaces import builtin_interfaces as _builtin_interfaces  # noqa: F401  (nested types)
from turtletui.interfaces._message import define_message as _msg

__all__ = [
    'Clock',
]

Clock = _msg('rosgraph_msgs/msg/Clock', '''\
# This message communicates the current time.
#
# For more information, see https://design.ros2.org/articles/clock_and_time.html.
builtin_interfaces/Time clock
''', globals())
