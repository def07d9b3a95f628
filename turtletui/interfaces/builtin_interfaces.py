"""builtin_interfaces/msg: Time and Duration.

Import path in ROS 2: builtin_interfaces.msg.
Definitions copied from the ROS 2 interface packages (Apache-2.0);
the text of each definition is what ``ros2 interface show`` prints.
"""

from turtletui.interfaces._message import define_message as _msg

__all__ = [
    'Duration',
    'Time',
]

Time = _msg('builtin_interfaces/msg/Time', '''\
# This message communicates ROS Time defined here:
# https://design.ros2.org/articles/clock_and_time.html

# The seconds component, valid over all int32 values.
int32 sec

# The nanoseconds component, valid in the range [0, 1e9).
uint32 nanosec
''', globals())

Duration = _msg('builtin_interfaces/msg/Duration', '''\
# Duration defines a period between two time points.
# Messages of this datatype are of ROS Time following this design:
# https://design.ros2.org/articles/clock_and_time.html

# Seconds component, range is valid over any possible int32 value.
int32 sec

# Nanoseconds component in the range of [0, 1e9).
uint32 nanosec
''', globals())
