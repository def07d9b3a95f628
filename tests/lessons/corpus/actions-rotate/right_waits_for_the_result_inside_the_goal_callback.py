"""Right, though not the tutorial's way: waits for the result with
rclpy.spin_until_future_complete inside the goal response's done callback. rclpy
(Kilted, measured) spins the executor again there: a done callback is a task of no
callback group, so the result is taken meanwhile and the next goal is sent from it."""
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
        result_future = goal_handle.get_result_async()
        rclpy.spin_until_future_complete(self, result_future)
        self.result_callback(result_future)

    def feedback_callback(self, feedback_msg):
        remaining = feedback_msg.feedback.remaining
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
