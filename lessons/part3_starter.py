#!/usr/bin/env python3
"""Part 3 starter: your first node. Make it log a counter once a second.

Run it with:  turtletui run part3_starter.py
(or on a real ROS 2 machine:  python3 part3_starter.py)
"""

import rclpy
from rclpy.node import Node


class MyNode(Node):
    def __init__(self):
        super().__init__("first_node")
        # TODO 1: create the counter as an attribute of the node, starting at 0
        #         (self.counter_ = 0), so it keeps its value between callbacks.
        # TODO 2: create a timer that calls self.timer_callback every 1.0 s:
        #         self.create_timer(1.0, self.timer_callback)
        self.get_logger().info("First node has started")

    def timer_callback(self):
        # TODO 3: log the counter with self.get_logger().info(...),
        #         e.g. "Hello 0", then add one to it.
        pass


def main(args=None):
    rclpy.init(args=args)
    node = MyNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
