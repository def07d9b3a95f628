"""Part 5 with a sleep in the pose callback: each line is right for a pose that is by then old."""

import time

import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class PoseLogger(Node):
    def __init__(self):
        super().__init__("pose_logger")
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, msg):
        self.get_logger().info(f"x={msg.x:.2f} y={msg.y:.2f}")
        time.sleep(0.2)  # "so the log is not flooded": the poses queue up behind it


def main():
    rclpy.init()
    rclpy.spin(PoseLogger())


if __name__ == "__main__":
    main()
