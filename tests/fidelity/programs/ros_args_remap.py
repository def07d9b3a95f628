"""Command-line ROS arguments given to rclpy.init(args=...): a topic remapped with -r, a node
moved by a remap for it alone (node:__ns:=), parameters from -p (YAML types) taken up by
declare_parameter, -p for one node, remove_ros_args, a node's own cli_args renaming it, and
use_global_arguments=False."""
import rclpy
from rclpy.node import Node
from rclpy.utilities import remove_ros_args
from std_msgs.msg import String

ARGS = [
    "prog.py", "--verbose", "--ros-args",
    "-r", "chatter:=talk", "-r", "driver:__ns:=/robot",
    "-p", "speed:=1.5", "-p", "laps:=3", "-p", "name:=leo", "-p", "flags:=[true, false]",
    "-p", "ids:=[1, 2, 3]", "-p", "quoted:='42'", "-p", "driver:gain:=0.5",
    "--", "after",
]
DEFAULTS = (("speed", 0.0), ("laps", 0), ("name", ""), ("flags", [False]), ("ids", [0]), ("quoted", ""), ("gain", 1.0))


def main():
    print("user args:", remove_ros_args(args=ARGS))
    rclpy.init(args=ARGS)
    driver = Node("driver")
    other = Node("other")
    for node in (driver, other):
        print(node.get_fully_qualified_name(), node.resolve_topic_name("chatter"), node.resolve_topic_name("/chatter"))
        print("  publisher topic:", node.create_publisher(String, "chatter", 10).topic_name)
        print("  subscription topic:", node.create_subscription(String, "chatter", print, 10).topic_name)
        for name, default in DEFAULTS:
            p = node.declare_parameter(name, default)
            print("  ", name, p.type_.name, p.value)
    renamed = Node("original", cli_args=["--ros-args", "-r", "__node:=renamed", "-p", "speed:=9.0"])
    print("cli_args:", renamed.get_fully_qualified_name(), renamed.declare_parameter("speed", 0.0).value)
    isolated = Node("isolated", use_global_arguments=False)
    print("isolated:", isolated.resolve_topic_name("chatter"), isolated.declare_parameter("speed", 0.0).value)
    for node in (driver, other, renamed, isolated):
        node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
