"""Right, written differently: the scan callback stores the scan, a 20 Hz
timer decides; other sector widths and distances."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import LaserScan


class Roamer(Node):
    def __init__(self):
        super().__init__("roamer")
        self.scan = None
        self.turning = 0.0
        self.cmd = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(LaserScan, "/turtle1/scan", self.keep, qos_profile_sensor_data)
        self.create_timer(0.05, self.decide)

    def keep(self, scan):
        self.scan = scan

    def nearest(self, low, high):
        scan = self.scan
        best = scan.range_max
        for i, r in enumerate(scan.ranges):
            a = math.remainder(scan.angle_min + i * scan.angle_increment, math.tau)
            if low <= a <= high and math.isfinite(r):
                best = min(best, max(r, scan.range_min))
        return best

    def decide(self):
        if self.scan is None:
            return
        front = self.nearest(-0.6, 0.6)
        cmd = Twist()
        if self.turning == 0.0 and front < 0.8:
            self.turning = 1.0 if self.nearest(0.6, 1.6) > self.nearest(-1.6, -0.6) else -1.0
        elif self.turning != 0.0 and front > 1.2:
            self.turning = 0.0
        if self.turning:
            cmd.angular.z = 1.8 * self.turning
        else:
            cmd.linear.x = 1.2
        self.cmd.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Roamer())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
