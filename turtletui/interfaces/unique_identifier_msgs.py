"""unique_identifier_msgs/msg: UUID (goal ids of actions).

Import path in ROS 2: unique_identifier_msgs.msg.
Definitions copied from the ROS 2 interface packages (Apache-2.0);
the text of each definition is what ``ros2 interface show`` prints.
"""

from turtletui.interfaces._message import define_message as _msg

__all__ = [
    'UUID',
]

UUID = _msg('unique_identifier_msgs/msg/UUID', '''\
# A universally unique identifier (UUID).
#
#  http://en.wikipedia.org/wiki/Universally_unique_identifier
#  http://tools.ietf.org/html/rfc4122.html

uint8[16] uuid
''', globals())
