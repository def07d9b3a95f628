"""Right, written differently: the parameters read together with
get_parameters in the pose callback, and logged when they change."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose

NAMES = ["speed", "slow_speed", "turn_rate", "box_min", "box_max"]


class Avoider(Node):
    def __init__(self):
        super().__init__("avoider")
        self.declare_parameters("", [("speed", 5.0), ("slow_speed", 1.0), ("turn_rate", 1.5), ("box_min", 2.0), ("box_max", 9.0)])
        self.last = None
        self.cmd_pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose):
        speed, slow, turn, low, high = (p.value for p in self.get_parameters(NAMES))
        if (speed, slow, turn, low, high) != self.last:
            self.last = (speed, slow, turn, low, high)
            self.get_logger().info(f"speed {speed}, slow {slow}, turn {turn}, box {low}..{high}")
        cmd = Twist()
        if pose.x < low or pose.x > high or pose.y < low or pose.y > high:
            cmd.linear.x, cmd.angular.z = slow, turn
        else:
            cmd.linear.x = speed
        self.cmd_pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Avoider())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
