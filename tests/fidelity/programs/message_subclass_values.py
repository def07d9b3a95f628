"""Values of int, float and str subclasses (numpy.float64, an IntEnum, a str subclass) set in
message fields: the sender keeps them, the subscriber gets plain int, float and str (CDR)."""
import enum

import numpy as np
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import Int32, String


class Colour(enum.IntEnum):
    RED = 3


class Name(str):
    pass


def main():
    rclpy.init()
    node = Node("subclasses")
    got = []
    node.create_subscription(Twist, "tw", got.append, 10)
    node.create_subscription(Int32, "i", got.append, 10)
    node.create_subscription(String, "s", got.append, 10)
    tw = node.create_publisher(Twist, "tw", 10)
    i = node.create_publisher(Int32, "i", 10)
    s = node.create_publisher(String, "s", 10)
    msg = Twist()
    msg.linear.x = np.float64(1.5)
    msg.angular.z = float(np.float32(0.25))
    print(repr(msg.linear.x), msg)
    tw.publish(msg)
    imsg = Int32(data=Colour.RED)
    print(repr(imsg.data), imsg)
    i.publish(imsg)
    smsg = String(data=Name("abc"))
    print(repr(smsg.data), type(smsg.data).__name__)
    s.publish(smsg)
    for _ in range(5):
        rclpy.spin_once(node, timeout_sec=0.2)
    for m in got:
        print(m)
        for field in m.get_fields_and_field_types():
            v = getattr(m, field)
            print(" ", field, type(v).__name__, repr(v))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
