"""SLOT_TYPES of the message classes a course uses, as a program sees them: printed
(rosidl_parser.definition objects), counted, zipped with get_fields_and_field_types(),
walked recursively to describe a message, compared, and tested with isinstance."""
import rosidl_parser.definition as definition
from geometry_msgs.msg import Pose, PoseStamped, Twist, Vector3
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Byte, Char, Float32MultiArray, Header, String
from std_srvs.srv import Empty, SetBool, Trigger
from turtlesim_msgs.msg import Pose as TurtlePose
from turtlesim_msgs.srv import Spawn

CLASSES = (Twist, Vector3, Pose, PoseStamped, TurtlePose, String, Header, Float32MultiArray, Char, Byte,
           LaserScan, SetBool.Request, Trigger.Response, Empty.Request, Spawn.Request, Spawn.Event)


def describe(slot_type):
    """A field type the way a generic message printer would name it."""
    if isinstance(slot_type, definition.BasicType):
        return slot_type.typename
    if isinstance(slot_type, definition.NamespacedType):
        return "/".join(slot_type.namespaced_name())
    if isinstance(slot_type, definition.AbstractGenericString):
        bound = f"<={slot_type.maximum_size}" if slot_type.has_maximum_size() else ""
        return type(slot_type).__name__ + bound
    if isinstance(slot_type, definition.Array):
        return f"{describe(slot_type.value_type)}[{slot_type.size}]"
    if isinstance(slot_type, definition.BoundedSequence):
        return f"{describe(slot_type.value_type)}[<={slot_type.maximum_size}]"
    if isinstance(slot_type, definition.UnboundedSequence):
        return f"{describe(slot_type.value_type)}[]"
    return repr(slot_type)


def walk(msg, indent=""):
    """Print a message's fields recursively, as a student's generic echo does."""
    for (name, text), slot_type in zip(msg.get_fields_and_field_types().items(), msg.SLOT_TYPES, strict=True):
        value = getattr(msg, name)
        if isinstance(slot_type, definition.NamespacedType):
            print(f"{indent}{name}: ({text})")
            walk(value, indent + "  ")
        elif isinstance(slot_type, definition.AbstractSequence):
            print(f"{indent}{name}: {len(value)} x {describe(slot_type.value_type)}")
        else:
            print(f"{indent}{name}: {value!r} ({describe(slot_type)})")


def main():
    for cls in CLASSES:
        fields = cls.get_fields_and_field_types()
        print(cls.__name__, len(cls.SLOT_TYPES), len(fields), type(cls.SLOT_TYPES).__name__)
        print("  ", cls.SLOT_TYPES)
        print("  ", [(name, type(t).__name__, describe(t)) for name, t in zip(fields, cls.SLOT_TYPES, strict=True)])
    print("instance sees the class's:", Twist().SLOT_TYPES is Twist.SLOT_TYPES)
    print("equal:", Twist.SLOT_TYPES[0] == Twist.SLOT_TYPES[1], Vector3.SLOT_TYPES[0] == TurtlePose.SLOT_TYPES[0])
    print("same types as ROS writes them:", LaserScan.SLOT_TYPES[8] == definition.UnboundedSequence(definition.BasicType("float")),
          Pose.SLOT_TYPES[0] == definition.NamespacedType(["geometry_msgs", "msg"], "Point"))
    try:
        hash(Twist.SLOT_TYPES[0])
    except TypeError as err:
        print("hash:", err)
    print("namespaces:", Twist.SLOT_TYPES[0].namespaces, Twist.SLOT_TYPES[0].name)
    walk(PoseStamped())
    walk(LaserScan(ranges=[1.0, 2.0]))
    walk(TurtlePose(x=1.5))


if __name__ == "__main__":
    main()
