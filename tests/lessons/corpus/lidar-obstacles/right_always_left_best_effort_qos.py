"""Right, written differently: a best-effort QoSProfile of its own, the front sector by index
modulo the beam count, -inf read as range_min, and always turning left."""
import math

import rclpy
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan


class AlwaysLeft(Node):
    """Turns left whenever the front is blocked, until it is clear again."""

    def __init__(self):
        super().__init__("obstacle_avoider")
        qos = QoSProfile(depth=5, reliability=ReliabilityPolicy.BEST_EFFORT)
        self.sub = self.create_subscription(LaserScan, "/turtle1/scan", self.cb, qos)
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.blocked = False

    def cb(self, scan: LaserScan):
        n = len(scan.ranges)
        width = int(round(math.radians(35) / scan.angle_increment))
        front = [scan.ranges[i % n] for i in range(-width, width + 1)]
        front = [r for r in front if not math.isnan(r)]
        front = [scan.range_min if r == -math.inf else r for r in front]
        closest = min(front, default=math.inf)
        if closest < 0.9:
            self.blocked = True
        elif closest > 1.4:
            self.blocked = False
        cmd = Twist()
        if self.blocked:
            cmd.angular.z = 1.8
        else:
            cmd.linear.x = 1.5
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(AlwaysLeft())


if __name__ == "__main__":
    main()
