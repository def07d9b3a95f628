"""Cheat: logs on every pose, but always the first pose it received."""
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class PoseSubscriberNode(Node):
    def __init__(self):
        super().__init__("pose_subscriber")
        self.first_ = None
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, msg: Pose):
        if self.first_ is None:
            self.first_ = (msg.x, msg.y)
        self.get_logger().info(f"({self.first_[0]}, {self.first_[1]})")


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(PoseSubscriberNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
