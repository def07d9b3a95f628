"""Wrong: the labels swapped (x= before msg.y, y= before msg.x): each line names
the coordinates wrongly."""
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class PoseSubscriberNode(Node):
    def __init__(self):
        super().__init__("pose_subscriber")
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, msg: Pose):
        self.get_logger().info(f"x={msg.y:.2f} y={msg.x:.2f}")


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(PoseSubscriberNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
