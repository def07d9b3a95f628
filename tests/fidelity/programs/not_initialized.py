"""A node made before rclpy.init() or after shutdown, shutting down twice, a destroyed node's publisher."""
import rclpy
from rclpy.exceptions import InvalidHandle, NotInitializedException
from rclpy.node import Node
from std_msgs.msg import String


def main():
    try:
        Node("too_early")
    except NotInitializedException as err:
        print("before init:", type(err).__name__, err)
    rclpy.init()
    print("ok after init:", rclpy.ok())
    node = Node("short_lived")
    node.destroy_node()
    try:
        node.create_publisher(String, "chatter", 10)
    except InvalidHandle as err:
        print("destroyed node:", type(err).__name__, isinstance(err, RuntimeError), err)
    rclpy.shutdown()
    print("ok after shutdown:", rclpy.ok())
    try:
        Node("too_late")
    except NotInitializedException as err:
        print("after shutdown:", type(err).__name__, err)
    try:
        rclpy.shutdown()
    except RuntimeError as err:
        print("shutdown twice:", type(err).__name__, err)


if __name__ == "__main__":
    main()
