"""example_interfaces: AddTwoInts, Fibonacci and the tutorials' simple types.

Import paths in ROS 2: example_interfaces.msg, example_interfaces.srv, example_interfaces.action.
Definitions copied from the ROS 2 interface packages (Apache-2.0) by
scripts/interfaces_from_ros.py: the text of each is its file's, byte for byte.
"""

from turtletui.interfaces import action_msgs as _action_msgs  # noqa: F401  (nested types)
from turtletui.interfaces import builtin_interfaces as _builtin_interfaces  # noqa: F401  (nested types)
from turtletui.interfaces import unique_identifier_msgs as _unique_identifier_msgs  # noqa: F401  (nested types)
from turtletui.interfaces._message import define_action as _action
from turtletui.interfaces._message import define_message as _msg
from turtletui.interfaces._message import define_service as _srv

__all__ = [
    'AddTwoInts',
    'Bool',
    'Byte',
    'ByteMultiArray',
    'Char',
    'Empty',
    'Fibonacci',
    'Float32',
    'Float32MultiArray',
    'Float64',
    'Float64MultiArray',
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
    'SetBool',
    'String',
    'Trigger',
    'UInt16',
    'UInt16MultiArray',
    'UInt32',
    'UInt32MultiArray',
    'UInt64',
    'UInt64MultiArray',
    'UInt8',
    'UInt8MultiArray',
    'WString',
]

Bool = _msg('example_interfaces/msg/Bool', '''\
# This is an example message of using a primitive datatype, bool.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
bool data
''', globals())

Byte = _msg('example_interfaces/msg/Byte', '''\
# This is an example message of using a primitive datatype, byte.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
byte data
''', globals())

MultiArrayDimension = _msg('example_interfaces/msg/MultiArrayDimension', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

string label   # label of given dimension
uint32 size    # size of given dimension (in type units)
uint32 stride  # stride of given dimension
''', globals())

MultiArrayLayout = _msg('example_interfaces/msg/MultiArrayLayout', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

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

ByteMultiArray = _msg('example_interfaces/msg/ByteMultiArray', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
byte[]            data          # array of data
''', globals())

Char = _msg('example_interfaces/msg/Char', '''\
# This is an example message of using a primitive datatype, char.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
char data
''', globals())

Empty = _msg('example_interfaces/msg/Empty', '''\
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
''', globals())

Float32 = _msg('example_interfaces/msg/Float32', '''\
# This is an example message of using a primitive datatype, float32.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
float32 data
''', globals())

Float32MultiArray = _msg('example_interfaces/msg/Float32MultiArray', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
float32[]         data          # array of data
''', globals())

Float64 = _msg('example_interfaces/msg/Float64', '''\
# This is an example message of using a primitive datatype, float64.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
float64 data
''', globals())

Float64MultiArray = _msg('example_interfaces/msg/Float64MultiArray', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
float64[]         data          # array of data
''', globals())

Int16 = _msg('example_interfaces/msg/Int16', '''\
# This is an example message of using a primitive datatype, int16.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
int16 data
''', globals())

Int16MultiArray = _msg('example_interfaces/msg/Int16MultiArray', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
int16[]           data          # array of data
''', globals())

Int32 = _msg('example_interfaces/msg/Int32', '''\
# This is an example message of using a primitive datatype, int32.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
int32 data
''', globals())

Int32MultiArray = _msg('example_interfaces/msg/Int32MultiArray', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
int32[]           data          # array of data
''', globals())

Int64 = _msg('example_interfaces/msg/Int64', '''\
# This is an example message of using a primitive datatype, int64.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
int64 data
''', globals())

Int64MultiArray = _msg('example_interfaces/msg/Int64MultiArray', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
int64[]           data          # array of data
''', globals())

Int8 = _msg('example_interfaces/msg/Int8', '''\
# This is an example message of using a primitive datatype, in8.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
int8 data
''', globals())

Int8MultiArray = _msg('example_interfaces/msg/Int8MultiArray', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
int8[]            data          # array of data
''', globals())

String = _msg('example_interfaces/msg/String', '''\
# This is an example message of using a primitive datatype, string.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
string data
''', globals())

UInt16 = _msg('example_interfaces/msg/UInt16', '''\
# This is an example message of using a primitive datatype, uint16.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
uint16 data
''', globals())

UInt16MultiArray = _msg('example_interfaces/msg/UInt16MultiArray', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
uint16[]            data        # array of data
''', globals())

UInt32 = _msg('example_interfaces/msg/UInt32', '''\
# This is an example message of using a primitive datatype, uint32.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
uint32 data
''', globals())

UInt32MultiArray = _msg('example_interfaces/msg/UInt32MultiArray', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
uint32[]          data          # array of data
''', globals())

UInt64 = _msg('example_interfaces/msg/UInt64', '''\
# This is an example message of using a primitive datatype, unint64.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
uint64 data
''', globals())

UInt64MultiArray = _msg('example_interfaces/msg/UInt64MultiArray', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
uint64[]          data          # array of data
''', globals())

UInt8 = _msg('example_interfaces/msg/UInt8', '''\
# This is an example message of using a primitive datatype, uint8.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
uint8 data
''', globals())

UInt8MultiArray = _msg('example_interfaces/msg/UInt8MultiArray', '''\
# This is an example of using complex datatypes.
# It is not recommended to use directly.
# To use a similar datastruct please define a custom message with appropriate semantic meaning.

# Please look at the MultiArrayLayout message definition for
# documentation on all multiarrays.

MultiArrayLayout  layout        # specification of data layout
uint8[]           data          # array of data
''', globals())

WString = _msg('example_interfaces/msg/WString', '''\
# This is an example message of using a primitive datatype, wstring.
# If you want to test with this that's fine, but if you are deploying
# it into a system you should create a semantically meaningful message type.
# If you want to embed it in another message, use the primitive data type instead.
wstring data
''', globals())

AddTwoInts = _srv('example_interfaces/srv/AddTwoInts', '''\
int64 a
int64 b
---
int64 sum
''', globals())

SetBool = _srv('example_interfaces/srv/SetBool', '''\
# This is an example of a service to set a boolean value.
# This can be used for testing but a semantically meaningful
# one should be created to be built upon.

bool data # e.g. for hardware enabling / disabling
---
bool success   # indicate successful run of triggered service
string message # informational, e.g. for error messages
''', globals())

Trigger = _srv('example_interfaces/srv/Trigger', '''\
# An example of a trigger service.
# This can be used for testing but a semantically meaningful
# one should be created to be built upon.

---
bool success   # indicate successful run of triggered service
string message # informational, e.g. for error messages.
''', globals())

Fibonacci = _action('example_interfaces/action/Fibonacci', '''\
# Goal
int32 order
---
# Result
int32[] sequence
---
# Feedback
int32[] sequence
''', globals())
