"""Right, written differently: each coordinate named, y before x ("row y=..., column x=..."):
every line still says where the turtle is."""
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class PoseSubscriberNode(Node):
    def __init__(self):
        super().__init__("pose_subscriber")
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, msg: Pose):
        self.get_logger().info(f"row y={msg.y:.3f}, column x={msg.x:.3f}")


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(PoseSubscriberNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
