"""Right, written differently: headings written in degrees and converted with
math.radians, the feedback logged with %-formatting."""
import math

import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute

DEGREES = [90, 180, -90, 0]


class Compass(Node):
    def __init__(self):
        super().__init__("compass")
        self.client = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")
        self.next_index = 0
        self.client.wait_for_server()
        self.send()

    def send(self):
        if self.next_index == len(DEGREES):
            self.get_logger().info("done")
            return
        goal = RotateAbsolute.Goal(theta=math.radians(DEGREES[self.next_index]))
        self.next_index += 1
        future = self.client.send_goal_async(goal, feedback_callback=self.on_feedback)
        future.add_done_callback(self.on_accepted)

    def on_accepted(self, future):
        future.result().get_result_async().add_done_callback(lambda _: self.send())

    def on_feedback(self, message):
        self.get_logger().info("Remaining %.3f rad" % message.feedback.remaining)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Compass())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
