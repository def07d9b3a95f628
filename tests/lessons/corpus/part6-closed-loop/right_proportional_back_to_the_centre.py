"""Right, written differently: once out of the 2..9 box, a P controller steers back towards
the centre (offset 0.6 rad) until the turtle is near it."""
import math

import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose

CENTRE = 5.5


class P(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.returning = False

    def pose_callback(self, pose):
        near = pose.x < 2.0 or pose.x > 9.0 or pose.y < 2.0 or pose.y > 9.0
        if near:
            self.returning = True
        elif abs(pose.x - CENTRE) < 1.5 and abs(pose.y - CENTRE) < 1.5:
            self.returning = False
        cmd = Twist()
        if self.returning:
            target = math.atan2(CENTRE - pose.y, CENTRE - pose.x) + 0.6
            err = math.atan2(math.sin(target - pose.theta), math.cos(target - pose.theta))
            cmd.angular.z = 4.0 * err
            cmd.linear.x = 1.5 if abs(err) < 1.0 else 0.5
        else:
            cmd.linear.x = 4.5
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(P())


if __name__ == "__main__":
    main()
