"""Right, written differently: the same Twist published from the pose callback (62.5 Hz),
a 1.5 m circle - still an open loop, the pose is never read."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class PoseTriggered(Node):
    """Publishes the same command whenever a pose arrives (62.5 Hz)."""

    def __init__(self):
        super().__init__("pose_triggered_circle")
        self.cmd = Twist()
        self.cmd.linear.x = 2.4
        self.cmd.angular.z = 1.6
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, _msg):
        self.pub.publish(self.cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(PoseTriggered())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
