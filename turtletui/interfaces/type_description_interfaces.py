"""type_description_interfaces: type descriptions and the GetTypeDescription service every node serves.

Import paths in ROS 2: type_description_interfaces.msg, type_description_interfaces.srv.
Definitions copied from the ROS 2 interface packages (Apache-2.0) by
scripts/interfaces_from_ros.py: the text of each is its file's, byte for byte.
"""

from turtletui.interfaces._message import define_message as _msg
from turtletui.interfaces._message import define_service as _srv

__all__ = [
    'Field',
    'FieldType',
    'GetTypeDescription',
    'IndividualTypeDescription',
    'KeyValue',
    'TypeDescription',
    'TypeSource',
]

FieldType = _msg('type_description_interfaces/msg/FieldType', '''\
# Represents the type of a field and related meta-data.

# A constant for each type supported according to:
#   http://design.ros2.org/articles/legacy_interface_definition.html
# and:
#   http://design.ros2.org/articles/idl_interface_definition.html
# Order is loosely coupled to the order of appearance in the IDL 4.2 spec:
#  https://www.omg.org/spec/IDL/4.2

# Layout of constants across the 0-255 decimal values in the uint8:
#
# - 000    : Reserved for "not set"
# - 001-048: Primitive types, strings, and reserved space for future primitive types
# - 049-096: Fixed sized array of primitive and string types
# - 097-144: Bounded Sequences of primitive and string types
# - 145-192: Unbounded Sequences of primitive and string types
# - 193-255: Reserved space for future array/sequence-like types

uint8 FIELD_TYPE_NOT_SET = 0

# Nested type defined in other .msg/.idl files.
uint8 FIELD_TYPE_NESTED_TYPE = 1

# Integer Types
uint8 FIELD_TYPE_INT8 = 2
uint8 FIELD_TYPE_UINT8 = 3
uint8 FIELD_TYPE_INT16 = 4
uint8 FIELD_TYPE_UINT16 = 5
uint8 FIELD_TYPE_INT32 = 6
uint8 FIELD_TYPE_UINT32 = 7
uint8 FIELD_TYPE_INT64 = 8
uint8 FIELD_TYPE_UINT64 = 9

# Floating-Point Types
uint8 FIELD_TYPE_FLOAT = 10
uint8 FIELD_TYPE_DOUBLE = 11
uint8 FIELD_TYPE_LONG_DOUBLE = 12

# Char and WChar Types
uint8 FIELD_TYPE_CHAR = 13
uint8 FIELD_TYPE_WCHAR = 14

# Boolean Type
uint8 FIELD_TYPE_BOOLEAN = 15

# Byte/Octet Type
uint8 FIELD_TYPE_BYTE = 16

# String Types
uint8 FIELD_TYPE_STRING = 17
uint8 FIELD_TYPE_WSTRING = 18

# Fixed String Types
uint8 FIELD_TYPE_FIXED_STRING = 19
uint8 FIELD_TYPE_FIXED_WSTRING = 20

# Bounded String Types
uint8 FIELD_TYPE_BOUNDED_STRING = 21
uint8 FIELD_TYPE_BOUNDED_WSTRING = 22

# Fixed Sized Array Types
uint8 FIELD_TYPE_NESTED_TYPE_ARRAY = 49
uint8 FIELD_TYPE_INT8_ARRAY = 50
uint8 FIELD_TYPE_UINT8_ARRAY = 51
uint8 FIELD_TYPE_INT16_ARRAY = 52
uint8 FIELD_TYPE_UINT16_ARRAY = 53
uint8 FIELD_TYPE_INT32_ARRAY = 54
uint8 FIELD_TYPE_UINT32_ARRAY = 55
uint8 FIELD_TYPE_INT64_ARRAY = 56
uint8 FIELD_TYPE_UINT64_ARRAY = 57
uint8 FIELD_TYPE_FLOAT_ARRAY = 58
uint8 FIELD_TYPE_DOUBLE_ARRAY = 59
uint8 FIELD_TYPE_LONG_DOUBLE_ARRAY = 60
uint8 FIELD_TYPE_CHAR_ARRAY = 61
uint8 FIELD_TYPE_WCHAR_ARRAY = 62
uint8 FIELD_TYPE_BOOLEAN_ARRAY = 63
uint8 FIELD_TYPE_BYTE_ARRAY = 64
uint8 FIELD_TYPE_STRING_ARRAY = 65
uint8 FIELD_TYPE_WSTRING_ARRAY = 66
uint8 FIELD_TYPE_FIXED_STRING_ARRAY = 67
uint8 FIELD_TYPE_FIXED_WSTRING_ARRAY = 68
uint8 FIELD_TYPE_BOUNDED_STRING_ARRAY = 69
uint8 FIELD_TYPE_BOUNDED_WSTRING_ARRAY = 70

# Bounded Sequence Types
uint8 FIELD_TYPE_NESTED_TYPE_BOUNDED_SEQUENCE = 97
uint8 FIELD_TYPE_INT8_BOUNDED_SEQUENCE = 98
uint8 FIELD_TYPE_UINT8_BOUNDED_SEQUENCE = 99
uint8 FIELD_TYPE_INT16_BOUNDED_SEQUENCE = 100
uint8 FIELD_TYPE_UINT16_BOUNDED_SEQUENCE = 101
uint8 FIELD_TYPE_INT32_BOUNDED_SEQUENCE = 102
uint8 FIELD_TYPE_UINT32_BOUNDED_SEQUENCE = 103
uint8 FIELD_TYPE_INT64_BOUNDED_SEQUENCE = 104
uint8 FIELD_TYPE_UINT64_BOUNDED_SEQUENCE = 105
uint8 FIELD_TYPE_FLOAT_BOUNDED_SEQUENCE = 106
uint8 FIELD_TYPE_DOUBLE_BOUNDED_SEQUENCE = 107
uint8 FIELD_TYPE_LONG_DOUBLE_BOUNDED_SEQUENCE = 108
uint8 FIELD_TYPE_CHAR_BOUNDED_SEQUENCE = 109
uint8 FIELD_TYPE_WCHAR_BOUNDED_SEQUENCE = 110
uint8 FIELD_TYPE_BOOLEAN_BOUNDED_SEQUENCE = 111
uint8 FIELD_TYPE_BYTE_BOUNDED_SEQUENCE = 112
uint8 FIELD_TYPE_STRING_BOUNDED_SEQUENCE = 113
uint8 FIELD_TYPE_WSTRING_BOUNDED_SEQUENCE = 114
uint8 FIELD_TYPE_FIXED_STRING_BOUNDED_SEQUENCE = 115
uint8 FIELD_TYPE_FIXED_WSTRING_BOUNDED_SEQUENCE = 116
uint8 FIELD_TYPE_BOUNDED_STRING_BOUNDED_SEQUENCE = 117
uint8 FIELD_TYPE_BOUNDED_WSTRING_BOUNDED_SEQUENCE = 118

# Unbounded Sequence Types
uint8 FIELD_TYPE_NESTED_TYPE_UNBOUNDED_SEQUENCE = 145
uint8 FIELD_TYPE_INT8_UNBOUNDED_SEQUENCE = 146
uint8 FIELD_TYPE_UINT8_UNBOUNDED_SEQUENCE = 147
uint8 FIELD_TYPE_INT16_UNBOUNDED_SEQUENCE = 148
uint8 FIELD_TYPE_UINT16_UNBOUNDED_SEQUENCE = 149
uint8 FIELD_TYPE_INT32_UNBOUNDED_SEQUENCE = 150
uint8 FIELD_TYPE_UINT32_UNBOUNDED_SEQUENCE = 151
uint8 FIELD_TYPE_INT64_UNBOUNDED_SEQUENCE = 152
uint8 FIELD_TYPE_UINT64_UNBOUNDED_SEQUENCE = 153
uint8 FIELD_TYPE_FLOAT_UNBOUNDED_SEQUENCE = 154
uint8 FIELD_TYPE_DOUBLE_UNBOUNDED_SEQUENCE = 155
uint8 FIELD_TYPE_LONG_DOUBLE_UNBOUNDED_SEQUENCE = 156
uint8 FIELD_TYPE_CHAR_UNBOUNDED_SEQUENCE = 157
uint8 FIELD_TYPE_WCHAR_UNBOUNDED_SEQUENCE = 158
uint8 FIELD_TYPE_BOOLEAN_UNBOUNDED_SEQUENCE = 159
uint8 FIELD_TYPE_BYTE_UNBOUNDED_SEQUENCE = 160
uint8 FIELD_TYPE_STRING_UNBOUNDED_SEQUENCE = 161
uint8 FIELD_TYPE_WSTRING_UNBOUNDED_SEQUENCE = 162
uint8 FIELD_TYPE_FIXED_STRING_UNBOUNDED_SEQUENCE = 163
uint8 FIELD_TYPE_FIXED_WSTRING_UNBOUNDED_SEQUENCE = 164
uint8 FIELD_TYPE_BOUNDED_STRING_UNBOUNDED_SEQUENCE = 165
uint8 FIELD_TYPE_BOUNDED_WSTRING_UNBOUNDED_SEQUENCE = 166

# Identifying number for the type of the field, using one of the above constants.
uint8 type_id 0

# Only used when the type is an array or a bounded sequence.
# In the case of an array, this is the fixed capacity of the array.
# In the case of a bounded sequence, this is the maximum capacity of the sequence.
# In all other cases this field is unused.
uint64 capacity

# Only used when the type is a fixed or bounded string/wstring, or a array/sequence of those.
# In the case of a fixed string/wstring, it is the fixed length of the string.
# In the case of a bounded string/wstring, it is the maximum capacity of the string.
# In the case of an array/sequence of fixed string/wstring, it is the fixed length of the strings.
# In the case of an array/sequence of bounded string/wstring, it is the maximum capacity \
of the strings.
# It is not currently possible to have different string capacities per element in the \
array/sequence.
uint64 string_capacity

# Only used when the type is a nested type or array/sequence of nested types.
# This is limited to 255 characters.
# TODO(wjwwood): this 255 character limit was chosen due to this being the limit
#   for DDSI-RTPS based middlewares, which is the most commonly used right now.
#   We lack a ROS 2 specific limit in our design documents, but we should update
#   this and/or link to the design doc when that is available.
string<=255 nested_type_name
''', globals())

Field = _msg('type_description_interfaces/msg/Field', '''\
# Represents a single field in a type.

# Name of the field.
string name
# Type of the field, including details about the type like length, nested name, etc.
FieldType type
# Literal default value of the field as a string, as it appeared in the original
# message description file, whether that be .msg/.srv/.action or .idl.
string default_value
''', globals())

IndividualTypeDescription = _msg('type_description_interfaces/msg/IndividualTypeDescription', '''\
# Represents a single type, without the types it references, if any.

# Name of the type.
# This is limited to 255 characters.
# TODO(wjwwood): this 255 character limit was chosen due to this being the limit
#   for DDSI-RTPS based middlewares, which is the most commonly used right now.
#   We lack a ROS 2 specific limit in our design documents, but we should update
#   this and/or link to the design doc when that is available.
string<=255 type_name
# Fields of the type.
Field[] fields
''', globals())

KeyValue = _msg('type_description_interfaces/msg/KeyValue', '''\
# Represents an arbitrary key-value pair for application-specific information.

string key
string value
''', globals())

TypeDescription = _msg('type_description_interfaces/msg/TypeDescription', '''\
# Represents a complete type description, including the type itself as well as the types \
it references.

# Description of the type.
IndividualTypeDescription type_description
# Descriptions of all referenced types, recursively.
IndividualTypeDescription[] referenced_type_descriptions
''', globals())

TypeSource = _msg('type_description_interfaces/msg/TypeSource', '''\
# Represents the original source of a ROS 2 interface definition.

# ROS interface type name, in PACKAGE/NAMESPACE/TYPENAME format.
string type_name

# The type of the original source file, typically matching the file extension.
# Well-known encodings: "idl", "msg", "srv", "action", "dynamic", "implicit".
# "dynamic" specifies a type created programmatically by a user, thus having no source.
# "implicit" specifies a type created automatically as a subtype of a
# complex type (service or action) - such as the request message for a service.
# Implicit types will have no contents, the full source will be available on the parent srv/action.
string encoding

# Dumped contents of the interface definition source file.
# If `encoding` is "dynamic" or "implicit", this field will be empty.
string raw_file_contents
''', globals())

GetTypeDescription = _srv('type_description_interfaces/srv/GetTypeDescription', '''\
# ROS interface type name, in PACKAGE/NAMESPACE/TYPENAME format.
string type_name

# REP-2011 RIHS hash string.
string type_hash

# Whether to return the original idl/msg/etc. source file(s) in the response.
bool include_type_sources true
---
# True if the type description information is available and populated in the response.
# If false, all other fields except `failure_reason` are considered undefined.
bool successful
# If `successful` is false, contains a reason for failure.
# If `successful` is true, this is left empty.
string failure_reason

# The parsed type description which can be used programmatically.
TypeDescription type_description

# A list containing the interface definition source text of the requested type,
# plus all types it recursively depends on.
# Each source text is a copy of the original contents of the
# .msg, .srv, .action, .idl, or other file if it exists, including comments and whitespace.
# Sources can be matched with IndividualTypeDescriptions by their `type_name`.
# The `encoding` field of each entry informs how to interpret its contents.
TypeSource[] type_sources

# Key-value pairs of extra information.
KeyValue[] extra_information
''', globals())
