"""Wrong: a timer sends the next heading every 0.5 s instead of waiting for
the result. A quarter turn takes about 1.6 s at turtlesim's 1 rad/s, so every
goal is replaced before the turtle gets there."""
import math

import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute

HEADINGS = [math.pi / 2, math.pi, -math.pi / 2, 0.0]


class RotateClientNode(Node):
    def __init__(self):
        super().__init__("rotate_client")
        self.rotate_client_ = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")
        self.index_ = 0
        self.timer_ = self.create_timer(0.5, self.send_next_goal)

    def send_next_goal(self):
        if self.index_ >= len(HEADINGS):
            self.timer_.cancel()
            return
        goal = RotateAbsolute.Goal()
        goal.theta = HEADINGS[self.index_]
        self.index_ += 1
        self.rotate_client_.send_goal_async(goal, feedback_callback=self.feedback_callback)

    def feedback_callback(self, feedback_msg):
        self.get_logger().info(f"Remaining: {feedback_msg.feedback.remaining:.2f} rad")


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(RotateClientNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
