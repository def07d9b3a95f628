"""Wrong: /scan (a TurtleBot habit) instead of /turtle1/scan: nothing arrives, nothing drives."""
import math
import time

import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan


def closest(values, default):
    good = [r for r in values if math.isfinite(r)]
    return min(good) if good else default


class ObstacleAvoiderNode(Node):
    def __init__(self):
        super().__init__("obstacle_avoider")
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.scan_subscriber_ = self.create_subscription(
            LaserScan, "/scan", self.scan_callback, qos_profile_sensor_data
        )
        self.turn_ = 0.0

    def scan_callback(self, scan: LaserScan):
        r = list(scan.ranges)
        front = closest(r[:7] + r[-6:], scan.range_max)
        left = closest(r[7:19], scan.range_max)
        right = closest(r[54:66], scan.range_max)
        cmd = Twist()
        if self.turn_ == 0.0 and front < 0.9:
            self.turn_ = 1.0 if left >= right else -1.0
        elif self.turn_ != 0.0 and front > 1.3:
            self.turn_ = 0.0
        if self.turn_:
            cmd.angular.z = 2.0 * self.turn_
        else:
            cmd.linear.x = 1.5
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(ObstacleAvoiderNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
