"""Wrong: sends all four goals at once and never waits for a result. Each new
goal replaces (aborts) the one before it, so the turtle only ever turns to
the last heading."""
import math

import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


class RotateClientNode(Node):
    def __init__(self):
        super().__init__("rotate_client")
        self.rotate_client_ = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")
        self.rotate_client_.wait_for_server()
        for theta in [math.pi / 2, math.pi, -math.pi / 2, 0.0]:
            goal = RotateAbsolute.Goal()
            goal.theta = theta
            self.rotate_client_.send_goal_async(goal, feedback_callback=self.feedback_callback)

    def feedback_callback(self, feedback_msg):
        self.get_logger().info(f"Remaining: {feedback_msg.feedback.remaining:.2f} rad")


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(RotateClientNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
