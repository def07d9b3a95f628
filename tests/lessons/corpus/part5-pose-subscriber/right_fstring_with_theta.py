"""Right, written differently: x, y and theta with two decimals, a start-up
line, and another node name."""
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class Watcher(Node):
    def __init__(self):
        super().__init__("watcher")
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.get_logger().info("watching /turtle1/pose")

    def on_pose(self, pose: Pose):
        self.get_logger().info(f"x={pose.x:.2f} y={pose.y:.2f} theta={pose.theta:.2f}")


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Watcher())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
