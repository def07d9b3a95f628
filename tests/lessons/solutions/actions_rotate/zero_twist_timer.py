"""Wrong: a timer publishes a zero Twist "to keep the turtle still" - and every
cmd_vel message aborts the rotate_absolute goal in progress."""
import math

import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.action import RotateAbsolute


class Rotator(Node):
    """Keeps the turtle 'safe' by publishing a zero Twist - which aborts every goal."""

    def __init__(self):
        super().__init__("rotator")
        self.client = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")
        self.stop = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.5, lambda: self.stop.publish(Twist()))
        self.headings = [math.pi / 2, math.pi, -math.pi / 2, 0.0]
        self.client.wait_for_server()
        self.send()

    def send(self):
        if not self.headings:
            return
        goal = RotateAbsolute.Goal(theta=self.headings.pop(0))
        fut = self.client.send_goal_async(goal, feedback_callback=self.fb)
        fut.add_done_callback(self.accepted)

    def accepted(self, fut):
        fut.result().get_result_async().add_done_callback(lambda _f: self.send())

    def fb(self, msg):
        self.get_logger().info(f"remaining {msg.feedback.remaining:.2f}")


def main():
    rclpy.init()
    rclpy.spin(Rotator())


if __name__ == "__main__":
    main()
