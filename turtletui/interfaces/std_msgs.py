"""std_msgs/msg: Header and the simple wrapper messages.

Import path in ROS 2: std_msgs.msg.
Definitions copied from the ROS 2 interface packages (Apache-2.0);
the text of each definition is what ``ros2 interface show`` prints.
"""

from turtletui.interfaces import builtin_interfaces as _builtin_interfaces  # noqa: F401  (nested types)
from turtletui.interfaces._message import define_message as _msg

__all__ = [
    'Bool',
    'ColorRGBA',
    'Empty',
    'Float32',
    'Float64',
    'Header',
    'Int16',
    'Int32',
    'Int64',
    'Int8',
    'String',
    'UInt16',
    'UInt32',
    'UInt64',
    'UInt8',
]

Header = _msg('std_msgs/msg/Header', '''\
# Standard metadata for higher-level stamped data types.
# This is generally used to communicate timestamped data
# in a particular coordinate frame.

# Two-integer timestamp that is expressed as seconds and nanoseconds.
builtin_interfaces/Time stamp

# Transform frame with which this data is associated.
string frame_id
''', globals())

String = _msg('std_msgs/msg/String', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

string data
''', globals())

Bool = _msg('std_msgs/msg/Bool', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

bool data
''', globals())

Empty = _msg('std_msgs/msg/Empty', '''\
''', globals())

Int8 = _msg('std_msgs/msg/Int8', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

int8 data
''', globals())

Int16 = _msg('std_msgs/msg/Int16', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

int16 data
''', globals())

Int32 = _msg('std_msgs/msg/Int32', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

int32 data
''', globals())

Int64 = _msg('std_msgs/msg/Int64', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

int64 data
''', globals())

UInt8 = _msg('std_msgs/msg/UInt8', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

uint8 data
''', globals())

UInt16 = _msg('std_msgs/msg/UInt16', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

uint16 data
''', globals())

UInt32 = _msg('std_msgs/msg/UInt32', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

uint32 data
''', globals())

UInt64 = _msg('std_msgs/msg/UInt64', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

uint64 data
''', globals())

Float32 = _msg('std_msgs/msg/Float32', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

float32 data
''', globals())

Float64 = _msg('std_msgs/msg/Float64', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in \
example_msgs.

float64 data
''', globals())

ColorRGBA = _msg('std_msgs/msg/ColorRGBA', '''\
float32 r
float32 g
float32 b
float32 a
''', globals())
