#!/usr/bin/env python3
"""Part 5 starter: a subscriber. Log the turtle's pose from the callback.

Run it with:  turtletui run part5_starter.py
(or on a real ROS 2 turtlesim:  python3 part5_starter.py)
"""

import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class PoseSubscriberNode(Node):
    def __init__(self):
        super().__init__("pose_subscriber")
        # TODO 1: subscribe to the turtle's pose: the type is Pose, the topic
        #         "/turtle1/pose" (check with: ros2 topic list -t), the callback
        #         self.pose_callback, and a queue size of 10.
        #         self.pose_subscriber_ = self.create_subscription(...)
        self.get_logger().info("Pose subscriber has started")

    def pose_callback(self, msg: Pose):
        # TODO 2: log the position, e.g. "(" + str(msg.x) + ", " + str(msg.y) + ")",
        #         with self.get_logger().info(...).
        pass


def main(args=None):
    rclpy.init(args=args)
    node = PoseSubscriberNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
