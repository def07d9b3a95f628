"""Degenerate, open loop: publishes one fixed Twist from a timer, whatever
happens. Its parameters make the classic degenerate controllers:

- spinning in place: linear 0.0, angular 2.0 (the defaults)
- a fixed circle: linear 2.0, angular 1.0
- straight ahead: linear 2.0, angular 0.0
"""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class FixedTwist(Node):
    def __init__(self):
        super().__init__("fixed_twist")
        self.declare_parameter("linear", 0.0)
        self.declare_parameter("angular", 2.0)
        self.declare_parameter("period", 0.1)
        self.publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(self.get_parameter("period").value, self.send)

    def send(self):
        cmd = Twist()
        cmd.linear.x = self.get_parameter("linear").value
        cmd.angular.z = self.get_parameter("angular").value
        self.publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(FixedTwist())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
