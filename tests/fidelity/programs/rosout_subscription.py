"""A subscription to /rosout hears the log lines of every node of the program, its own
included, as rcl_interfaces/msg/Log (stamp, level, logger name, message, file, function,
line); a child logger's lines come through its node; a logger of no node reaches no one;
a node that logs in its /rosout callback hears that line too."""
import os

import rclpy
from _discovery import spin_until
from rcl_interfaces.msg import Log
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node


def main():
    rclpy.init()
    listener = Node("listener")
    talker = Node("talker", namespace="/lab")
    executor = SingleThreadedExecutor()
    executor.add_node(listener)
    executor.add_node(talker)
    heard = []

    def on_log(msg):
        heard.append(msg)
        if msg.msg == "careful":
            listener.get_logger().info(f"heard {msg.name} say {msg.msg}")

    listener.create_subscription(Log, "/rosout", on_log, 10)
    ours = [i.node_name for i in listener.get_publishers_info_by_topic("/rosout") if i.node_name != "turtlesim"]
    print("publishers", sorted(ours))
    for _ in range(10):
        executor.spin_once(timeout_sec=0.05)
    listener.get_logger().info("hello")
    talker.get_logger().warning("careful")
    talker.get_logger().get_child("part").error("from a child logger")
    rclpy.logging.get_logger("loose").info("from no node")
    listener.get_logger().debug("below the level")
    print("heard all", spin_until(executor, lambda: len(heard) >= 4))
    for msg in heard:
        print(
            msg.level, msg.name, repr(msg.msg), os.path.basename(msg.file), msg.function, msg.line,
            msg.stamp.sec > 1_600_000_000, type(msg.level).__name__,
        )
    print("levels", Log.DEBUG, Log.INFO, Log.WARN, Log.ERROR, Log.FATAL)
    talker.destroy_node()
    listener.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
