"""Right, written differently: %-formatting through a helper, and every 50
poses an extra line with a count."""
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose


class PoseLogger(Node):
    def __init__(self):
        super().__init__("pose_logger")
        self.count = 0
        self.sub = self.create_subscription(Pose, "/turtle1/pose", self.callback, 10)

    def report(self, x, y):
        self.get_logger().info("Pose: (%.3f, %.3f)" % (x, y))

    def callback(self, msg):
        self.count += 1
        self.report(msg.x, msg.y)
        if self.count % 50 == 0:
            self.get_logger().info("still listening (%d poses)" % self.count)


def main(args=None):
    rclpy.init(args=args)
    node = PoseLogger()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    rclpy.shutdown()


if __name__ == "__main__":
    main()
