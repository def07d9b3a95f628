"""Wrong: main() creates the node and returns without spinning it: the callback
never runs, and no error says why."""
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class PoseSubscriberNode(Node):
    def __init__(self):
        super().__init__("pose_subscriber")
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, msg):
        self.get_logger().info(f"({msg.x}, {msg.y})")


def main():
    rclpy.init()
    node = PoseSubscriberNode()
    node.get_logger().info("node started")
    rclpy.shutdown()


if __name__ == "__main__":
    main()
