"""Right: numpy over the scan, latest scan kept and commands from a 20 Hz timer, slows down in front of things."""
import numpy as np

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import LaserScan


class Avoider(Node):
    def __init__(self):
        super().__init__("np_avoider")
        self.scan = None
        self.side = 0
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(LaserScan, "/turtle1/scan", self.keep, qos_profile_sensor_data)
        self.create_timer(0.05, self.step)

    def keep(self, scan):
        self.scan = scan

    def step(self):
        if self.scan is None:
            return
        s = self.scan
        r = np.asarray(s.ranges, dtype=float)
        r = np.where(np.isnan(r), s.range_max, r)
        r = np.where(np.isinf(r) & (r > 0), s.range_max, r)
        r = np.where(np.isinf(r), s.range_min, r)
        ang = np.arctan2(np.sin(s.angle_min + np.arange(len(r)) * s.angle_increment),
                         np.cos(s.angle_min + np.arange(len(r)) * s.angle_increment))
        front = r[np.abs(ang) <= np.radians(30)].min()
        left = r[(ang > np.radians(30)) & (ang <= np.radians(90))].min()
        right = r[(ang < -np.radians(30)) & (ang >= -np.radians(90))].min()
        cmd = Twist()
        if self.side == 0 and front < 0.9:
            self.side = 1 if left >= right else -1
        elif self.side != 0 and front > 1.4:
            self.side = 0
        if self.side:
            cmd.angular.z = 2.0 * self.side
        else:
            cmd.linear.x = float(min(1.8, 0.6 + front))
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(Avoider())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
