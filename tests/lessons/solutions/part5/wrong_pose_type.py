"""Wrong: subscribes to /turtle1/pose with geometry_msgs' Pose, not turtlesim's.
As on ROS 2 the subscription is made and never matches turtlesim's publisher:
the callback never runs, and no error."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Pose


class PoseSubscriberNode(Node):
    def __init__(self):
        super().__init__("pose_subscriber")
        self.pose_subscriber_ = self.create_subscription(
            Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, msg: Pose):
        self.get_logger().info("(" + str(msg.x) + ", " + str(msg.y) + ")")


def main(args=None):
    rclpy.init(args=args)
    node = PoseSubscriberNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == '__main__':
    main()
