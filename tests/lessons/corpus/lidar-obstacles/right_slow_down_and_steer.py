"""Right, written differently: slows down as the front closes in and steers
toward the more open side while it still moves."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import LaserScan


def closest(scan, low_deg, high_deg):
    values = [
        r if math.isfinite(r) else scan.range_max
        for i, r in enumerate(scan.ranges)
        if low_deg <= math.degrees(math.remainder(scan.angle_min + i * scan.angle_increment, math.tau)) <= high_deg
        and not math.isnan(r)
    ]
    return min(values, default=scan.range_max)


class Steerer(Node):
    def __init__(self):
        super().__init__("steerer")
        self.out = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(LaserScan, "/turtle1/scan", self.on_scan, qos_profile_sensor_data)
        self.side = 1.0

    def on_scan(self, scan):
        front = closest(scan, -25, 25)
        left = closest(scan, 25, 90)
        right = closest(scan, -90, -25)
        cmd = Twist()
        if front < 1.0:
            if front < 0.7:
                self.side = 1.0 if left >= right else -1.0
            cmd.linear.x = 0.0
            cmd.angular.z = 2.0 * self.side
        else:
            cmd.linear.x = min(1.6, 0.8 * front)
            cmd.angular.z = 0.3 * (left - right)
        self.out.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Steerer())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
