"""Part 4 with a callback that blocks for real (a socket that never answers): stopped, no traceback to read."""

import socket

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Circle(Node):
    def __init__(self):
        super().__init__("circle")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.5, self.tick)

    def tick(self):
        msg = Twist()
        msg.linear.x = 2.0
        msg.angular.z = 1.0
        self.pub.publish(msg)
        waiting, _ = socket.socketpair()
        waiting.recv(1)  # wall time: no simulated clock ends this wait


def main():
    rclpy.init()
    rclpy.spin(Circle())


if __name__ == "__main__":
    main()
