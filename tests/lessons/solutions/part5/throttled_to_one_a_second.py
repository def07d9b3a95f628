"""Wrong: logs the pose with throttle_duration_sec=1.0 - one line a second, not one per pose."""
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class PoseSubscriberNode(Node):
    def __init__(self):
        super().__init__("pose_subscriber")
        self.pose_subscriber_ = self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.last = None
        self.n = 0

    def pose_callback(self, msg: Pose):
        self.get_logger().info(f"({msg.x:.2f}, {msg.y:.2f})", throttle_duration_sec=1.0)


def main(args=None):
    rclpy.init(args=args)
    node = PoseSubscriberNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
