"""Wrong: the feedback callback reads feedback_msg.remaining instead of
feedback_msg.feedback.remaining: AttributeError on the first feedback, and the node stops."""

import math

import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute

# Compass headings in radians, in the order the turtle faces them.
HEADINGS = [math.pi / 2, math.pi, -math.pi / 2, 0.0]  # north, west, south, east


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
        goal_handle.get_result_async().add_done_callback(self.result_callback)

    def feedback_callback(self, feedback_msg):
        remaining = feedback_msg.remaining
        self.get_logger().info(f"Remaining: {remaining:.2f} rad", throttle_duration_sec=0.25)

    def result_callback(self, future):
        result = future.result().result
        self.get_logger().info(f"Goal done: delta = {result.delta:.2f} rad")
        self.index_ += 1
        self.send_next_goal()


def main(args=None):
    rclpy.init(args=args)
    node = RotateClientNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
