"""Publishing the wrong message type, or something that is not a message: a TypeError.

(The text differs on purpose: rclpy names its private modules, turtletui the topic and types.)"""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import String


def main():
    rclpy.init()
    node = Node("wrong_type")
    pub = node.create_publisher(Twist, "cmd_vel", 10)
    for bad in (String(data="go"), {"linear": {"x": 1.0}}, None):
        try:
            pub.publish(bad)
            print("published", type(bad).__name__)
        except TypeError as err:
            print("TypeError for", type(bad).__name__, isinstance(err, TypeError))
    pub.publish(Twist())
    print("a Twist is fine")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
