#!/usr/bin/env python3
"""Actions starter: turn turtle1 to face north, west, south and east in turn,
with rotate_absolute goals. Fill in the three callbacks.

Run it with:  turtletui run actions_rotate_starter.py
(or on a real ROS 2 turtlesim:  python3 actions_rotate_starter.py)
"""

import math

import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute

# Headings in radians: north, west, south, east.
HEADINGS = [math.pi / 2, math.pi, -math.pi / 2, 0.0]


class RotateClientNode(Node):
    def __init__(self):
        super().__init__("rotate_client")
        self.rotate_client_ = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")
        self.index_ = 0
        while not self.rotate_client_.wait_for_server(1.0):
            self.get_logger().warn("Waiting for the rotate_absolute action server...")
        self.send_next_goal()

    def send_next_goal(self):
        if self.index_ >= len(HEADINGS):
            self.get_logger().info("All four headings done")
            return
        goal = RotateAbsolute.Goal()
        goal.theta = HEADINGS[self.index_]
        self.get_logger().info(f"Sending goal: theta = {goal.theta:.2f} rad")
        future = self.rotate_client_.send_goal_async(goal, feedback_callback=self.feedback_callback)
        future.add_done_callback(self.goal_response_callback)

    def goal_response_callback(self, future):
        goal_handle = future.result()
        if not goal_handle.accepted:
            self.get_logger().error("Goal rejected")
            return
        # TODO 2: ask for the result: goal_handle.get_result_async() returns a
        #         future; add self.result_callback as its done callback.

    def feedback_callback(self, feedback_msg):
        # TODO 1: log feedback_msg.feedback.remaining, e.g. "Remaining: 0.42 rad"
        #         (add throttle_duration_sec=0.25 to keep the log readable).
        pass

    def result_callback(self, future):
        # TODO 3: log future.result().result.delta, then move on to the next
        #         heading (self.index_ += 1) and call self.send_next_goal().
        pass


def main(args=None):
    rclpy.init(args=args)
    node = RotateClientNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
