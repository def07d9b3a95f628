"""Right: a timer with a busy flag sends the next goal when the last result is in; headings accumulate (pi/2 * k)."""
import math
import time

import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute



class RotateClientNode(Node):
    def __init__(self):
        super().__init__("quarter_turns")
        self.client = ActionClient(self, RotateAbsolute, "turtle1/rotate_absolute")
        self.k = 1
        self.busy = False
        self.timer = self.create_timer(0.1, self.tick)

    def tick(self):
        if self.busy or not self.client.server_is_ready():
            return
        if self.k > 4:
            self.timer.cancel()
            return
        self.busy = True
        goal = RotateAbsolute.Goal(theta=self.k * math.pi / 2)
        future = self.client.send_goal_async(goal, feedback_callback=self.on_feedback)
        future.add_done_callback(self.on_accepted)

    def on_accepted(self, future):
        handle = future.result()
        handle.get_result_async().add_done_callback(self.on_result)

    def on_feedback(self, feedback_msg):
        self.get_logger().info("remaining %.3f" % feedback_msg.feedback.remaining)

    def on_result(self, future):
        self.get_logger().info("delta %.3f" % future.result().result.delta)
        self.k += 1
        self.busy = False


def main(args=None):
    rclpy.init(args=args)
    node = RotateClientNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
