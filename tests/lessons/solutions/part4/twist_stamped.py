"""Part 4 with the wrong message type: a TwistStamped on cmd_vel, which turtlesim never gets."""

import rclpy
from rclpy.node import Node
from geometry_msgs.msg import TwistStamped


class Circle(Node):
    def __init__(self):
        super().__init__("circle")
        self.pub = self.create_publisher(TwistStamped, "/turtle1/cmd_vel", 10)
        self.create_timer(0.1, self.tick)

    def tick(self):
        msg = TwistStamped()
        msg.twist.linear.x = 2.0
        msg.twist.angular.z = 1.0
        self.pub.publish(msg)


def main():
    rclpy.init()
    rclpy.spin(Circle())


if __name__ == "__main__":
    main()
