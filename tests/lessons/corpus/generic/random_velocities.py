"""Degenerate, open loop: a new random Twist every `period` seconds (forward
speed up to `max_linear` m/s, turn rate up to +-`max_angular` rad/s)."""

import random

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class RandomDriver(Node):
    def __init__(self):
        super().__init__("random_driver")
        self.declare_parameter("period", 0.5)
        self.declare_parameter("max_linear", 3.0)
        self.declare_parameter("max_angular", 3.0)
        self.publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(self.get_parameter("period").value, self.send)

    def send(self):
        cmd = Twist()
        cmd.linear.x = random.uniform(0.0, self.get_parameter("max_linear").value)
        turn = self.get_parameter("max_angular").value
        cmd.angular.z = random.uniform(-turn, turn)
        self.publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(RandomDriver())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
