"""Cheat: no action at all; turns to each heading with cmd_vel (a P
controller on theta), stops there, and logs "Remaining" lines as if it
followed a goal's feedback."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose

HEADINGS = [math.pi / 2, math.pi, -math.pi / 2, 0.0]


class Turner(Node):
    def __init__(self):
        super().__init__("rotate_client")
        self.index_ = 0
        self.still_ = 0
        self.publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose: Pose):
        if self.index_ >= len(HEADINGS):
            return
        error = math.remainder(HEADINGS[self.index_] - pose.theta, math.tau)
        cmd = Twist()
        if abs(error) > 0.01:
            cmd.angular.z = 3.0 * error
            self.get_logger().info(f"Remaining: {abs(error):.2f} rad", throttle_duration_sec=0.25)
        else:
            self.still_ += 1
            if self.still_ > 20:
                self.still_ = 0
                self.index_ += 1
        self.publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Turner())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
