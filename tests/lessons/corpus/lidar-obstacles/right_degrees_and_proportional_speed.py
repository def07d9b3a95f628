"""Right, written differently: sectors in degrees, speed proportional to the room ahead,
and a gentle steer towards the more open side while driving."""
import math

import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan


def sector_min(scan, lo_deg, hi_deg):
    best = scan.range_max
    for i, r in enumerate(scan.ranges):
        a = math.degrees(scan.angle_min + i * scan.angle_increment)
        a = (a + 180.0) % 360.0 - 180.0
        if lo_deg <= a <= hi_deg and math.isfinite(r):
            best = min(best, r)
    return best


class Avoider(Node):
    def __init__(self):
        super().__init__("avoider")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(LaserScan, "/turtle1/scan", self.on_scan, qos_profile_sensor_data)
        self.turning = 0.0

    def on_scan(self, scan):
        front = sector_min(scan, -35, 35)
        left = sector_min(scan, 35, 100)
        right = sector_min(scan, -100, -35)
        cmd = Twist()
        if front < 1.0:
            if self.turning == 0.0:
                self.turning = 1.0 if left > right else -1.0
            cmd.angular.z = 2.5 * self.turning
        else:
            if front > 1.4:
                self.turning = 0.0
            cmd.linear.x = min(2.0, 0.8 * front)
            cmd.angular.z = 0.6 * (left - right) / max(left + right, 0.1) + 1.5 * self.turning
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(Avoider())


if __name__ == "__main__":
    main()
