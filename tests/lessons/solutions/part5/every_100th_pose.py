"""Wrong: logs only every 100th pose, to keep the log quiet (about one line in
1.6 s instead of 62.5 a second)."""
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class PoseSubscriberNode(Node):
    def __init__(self):
        super().__init__("pose_subscriber")
        self.count_ = 0
        self.pose_subscriber_ = self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, msg: Pose):
        self.count_ += 1
        if self.count_ % 100 == 0:
            self.get_logger().info("(" + str(msg.x) + ", " + str(msg.y) + ")")


def main(args=None):
    rclpy.init(args=args)
    node = PoseSubscriberNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
