"""Right, written differently: turns (clockwise) only when near a wall and heading towards it,
driving at 3 m/s otherwise."""
import math

import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class HeadingAware(Node):
    """Turns only when near a wall AND heading towards it."""

    def __init__(self):
        super().__init__("turtle_controller")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.cb, 10)

    def cb(self, p: Pose):
        vx, vy = math.cos(p.theta), math.sin(p.theta)
        towards_wall = (p.x < 2.5 and vx < 0.3) or (p.x > 8.5 and vx > -0.3) or \
                       (p.y < 2.5 and vy < 0.3) or (p.y > 8.5 and vy > -0.3)
        cmd = Twist()
        if towards_wall:
            cmd.linear.x = 0.8
            cmd.angular.z = -2.0
        else:
            cmd.linear.x = 3.0
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(HeadingAware())


if __name__ == "__main__":
    main()
