"""Right, written differently: the callback keeps the latest pose and a 100 Hz timer logs it,
skipping the ticks before the first pose."""
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class LatestPose(Node):
    """Stores the latest pose and logs it from a 100 Hz timer."""

    def __init__(self):
        super().__init__("latest_pose")
        self.pose = None
        self.create_subscription(Pose, "/turtle1/pose", self.store, 10)
        self.create_timer(0.01, self.report)

    def store(self, msg):
        self.pose = msg

    def report(self):
        if self.pose is None:
            return
        self.get_logger().info(f"pose: {self.pose.x:.2f} {self.pose.y:.2f}")


def main():
    rclpy.init()
    rclpy.spin(LatestPose())


if __name__ == "__main__":
    main()
