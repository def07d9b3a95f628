"""Right, another way: the pose callback only stores the pose; a 20 Hz timer
computes each command from the latest one (other box and turn rate too)."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class WallAvoider(Node):
    def __init__(self):
        super().__init__("wall_avoider")
        self.latest = None
        self.cmd_pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.remember, 10)
        self.create_timer(0.05, self.control)
        self.get_logger().info("wall avoider: 20 Hz control loop")

    def remember(self, pose: Pose):
        self.latest = pose

    def control(self):
        if self.latest is None:
            return
        p = self.latest
        cmd = Twist()
        if p.x < 1.8 or p.x > 9.3 or p.y < 1.8 or p.y > 9.3:
            cmd.linear.x = 1.0
            cmd.angular.z = 2.0
        else:
            cmd.linear.x = 4.0
        self.cmd_pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = WallAvoider()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
