"""Degenerate: turns in place, one command per pose (parameter `turn`, rad/s):
as many commands as a closed loop sends, none of them depending on the pose."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class Spinner(Node):
    def __init__(self):
        super().__init__("spinner")
        self.declare_parameter("turn", 2.0)
        self.publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose: Pose):
        cmd = Twist()
        cmd.angular.z = self.get_parameter("turn").value
        self.publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Spinner())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
