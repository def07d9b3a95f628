"""Right: slices of ranges by index (ranges[-n:] + ranges[:n+1]), inf filtered with math.isfinite, proportional turn."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import LaserScan


class Avoider(Node):
    def __init__(self):
        super().__init__("avoider")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(LaserScan, "/turtle1/scan", self.on_scan, qos_profile_sensor_data)
        self.turning = 0.0

    def sector(self, scan, first_deg, last_deg):
        n = len(scan.ranges)
        a = int(round(math.radians(first_deg) / scan.angle_increment))
        b = int(round(math.radians(last_deg) / scan.angle_increment))
        values = [scan.ranges[i % n] for i in range(a, b + 1)]
        good = [r for r in values if math.isfinite(r)]
        return min(good, default=scan.range_max)

    def on_scan(self, scan):
        front = self.sector(scan, -35, 35)
        left = self.sector(scan, 35, 100)
        right = self.sector(scan, -100, -35)
        cmd = Twist()
        if self.turning == 0.0 and front < 1.0:
            self.turning = 1.0 if left > right else -1.0
        elif self.turning != 0.0 and front > 1.5:
            self.turning = 0.0
        if self.turning:
            cmd.angular.z = 2.5 * self.turning
        else:
            cmd.linear.x = 1.2
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(Avoider())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
