"""std_msgs: Header, ColorRGBA, the wrapper messages and the MultiArrays.

Import path in ROS 2: std_msgs.msg.
Definitions copied from the ROS 2 interface packages (Apache-2.0) by
scripts/interfaces_from_ros.py: the text of each is its file's, byte for byte.
"""

from turtletui.interfaces import builtin_interfaces as _builtin_interfaces  # noqa: F401  (nested types)
from turtletui.interfaces._message import define_message as _msg

__all__ = [
    'Bool',
    'Byte',
    'ByteMultiArray',
    'Char',
    'ColorRGBA',
    'Empty',
    'Float32',
    'Float32MultiArray',
    'Float64',
    'Float64MultiArray',
    'Header',
    'Int16',
    'Int16MultiArray',
    'Int32',
    'Int32MultiArray',
    'Int64',
    'Int64MultiArray',
    'Int8',
    'Int8MultiArray',
    'MultiArrayDimension',
    'MultiArrayLayout',
    'String',
    'UInt16',
    'UInt16MultiArray',
    'UInt32',
    'UInt32MultiArray',
    'UInt64',
    'UInt64MultiArray',
    'UInt8',
    'UInt8MultiArray',
]

Bool = _msg('std_msgs/msg/Bool', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

bool data
''', globals())

Byte = _msg('std_msgs/msg/Byte', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

byte data
''', globals())

MultiArrayDimension = _msg('std_msgs/msg/MultiArrayDimension', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

string label   # label of given dimension
uint32 size    # size of given dimension (in type units)
uint32 stride  # stride of given dimension
''', globals())

MultiArrayLayout = _msg('std_msgs/msg/MultiArrayLayout', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# The multiarray declares a generic multi-dimensional array of a
# particular data type.  Dimensions are ordered from outer most
# to inner most.
#
# Accessors should ALWAYS be written in terms of dimension stride
# and specified outer-most dimension first.
#
# multiarray(i,j,k) = data[data_offset + dim_stride[1]*i + dim_stride[2]*j + k]
#
# A standard, 3-channel 640x480 image with interleaved color channels
# would be specified as:
#
# dim[0].label  = "height"
# dim[0].size   = 480
# dim[0].stride = 3*640*480 = 921600  (note dim[0] stride is just size of image)
# dim[1].label  = "width"
# dim[1].size   = 640
# dim[1].stride = 3*640 = 1920
# dim[2].label  = "channel"
# dim[2].size   = 3
# dim[2].stride = 3
#
# multiarray(i,j,k) refers to the ith row, jth column, and kth channel.

MultiArrayDimension[] dim # Array of dimension properties
uint32 data_offset        # padding bytes at front of data
''', globals())

ByteMultiArray = _msg('std_msgs/msg/ByteMultiArray', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
byte[]            data          # array of data
''', globals())

Char = _msg('std_msgs/msg/Char', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

char data
''', globals())

ColorRGBA = _msg('std_msgs/msg/ColorRGBA', '''\
float32 r
float32 g
float32 b
float32 a
''', globals())

Empty = _msg('std_msgs/msg/Empty', '''\
''', globals())

Float32 = _msg('std_msgs/msg/Float32', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

float32 data
''', globals())

Float32MultiArray = _msg('std_msgs/msg/Float32MultiArray', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
float32[]         data          # array of data
''', globals())

Float64 = _msg('std_msgs/msg/Float64', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

float64 data
''', globals())

Float64MultiArray = _msg('std_msgs/msg/Float64MultiArray', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
float64[]         data          # array of data
''', globals())

Header = _msg('std_msgs/msg/Header', '''\
# Standard metadata for higher-level stamped data types.
# This is generally used to communicate timestamped data
# in a particular coordinate frame.

# Two-integer timestamp that is expressed as seconds and nanoseconds.
builtin_interfaces/Time stamp

# Transform frame with which this data is associated.
string frame_id
''', globals())

Int16 = _msg('std_msgs/msg/Int16', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

int16 data
''', globals())

Int16MultiArray = _msg('std_msgs/msg/Int16MultiArray', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
int16[]           data          # array of data
''', globals())

Int32 = _msg('std_msgs/msg/Int32', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

int32 data
''', globals())

Int32MultiArray = _msg('std_msgs/msg/Int32MultiArray', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
int32[]           data          # array of data
''', globals())

Int64 = _msg('std_msgs/msg/Int64', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

int64 data
''', globals())

Int64MultiArray = _msg('std_msgs/msg/Int64MultiArray', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
int64[]           data          # array of data
''', globals())

Int8 = _msg('std_msgs/msg/Int8', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

int8 data
''', globals())

Int8MultiArray = _msg('std_msgs/msg/Int8MultiArray', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
int8[]            data          # array of data
''', globals())

String = _msg('std_msgs/msg/String', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

string data
''', globals())

UInt16 = _msg('std_msgs/msg/UInt16', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

uint16 data
''', globals())

UInt16MultiArray = _msg('std_msgs/msg/UInt16MultiArray', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
uint16[]            data        # array of data
''', globals())

UInt32 = _msg('std_msgs/msg/UInt32', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

uint32 data
''', globals())

UInt32MultiArray = _msg('std_msgs/msg/UInt32MultiArray', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
uint32[]          data          # array of data
''', globals())

UInt64 = _msg('std_msgs/msg/UInt64', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

uint64 data
''', globals())

UInt64MultiArray = _msg('std_msgs/msg/UInt64MultiArray', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
uint64[]          data          # array of data
''', globals())

UInt8 = _msg('std_msgs/msg/UInt8', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

uint8 data
''', globals())

UInt8MultiArray = _msg('std_msgs/msg/UInt8MultiArray', '''\
# This was originally provided as an example message.
# It is deprecated as of Foxy
# It is recommended to create your own semantically meaningful message.
# However if you would like to continue using this please use the equivalent in example_msgs.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
uint8[]           data          # array of data
''', globals())
