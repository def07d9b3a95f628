# Right, with other numbers and another way to find the sectors: a narrower
# front sector found by index arithmetic, a slower cruise, keeps creeping while
# it turns, and picks the side with the larger mean reading.
import math

import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan


class ObstacleAvoiderNode(Node):
    def __init__(self):
        super().__init__('obstacle_avoider')
        self.cmd_vel_publisher_ = self.create_publisher(Twist, '/turtle1/cmd_vel', 10)
        self.scan_subscriber_ = self.create_subscription(LaserScan, '/turtle1/scan', self.scan_callback, qos_profile_sensor_data)
        self.turning_ = 0.0

    @staticmethod
    def cleaned(scan: LaserScan):
        """inf (nothing in range) counts as range_max; -inf as range_min; nan as range_max."""
        out = []
        for r in scan.ranges:
            if r == -math.inf:
                out.append(scan.range_min)
            elif math.isfinite(r):
                out.append(r)
            else:
                out.append(scan.range_max)
        return out

    def scan_callback(self, scan: LaserScan):
        ranges = self.cleaned(scan)
        k = round(math.radians(20) / scan.angle_increment)   # beams in 20 degrees
        side = round(math.radians(100) / scan.angle_increment)
        front = min(ranges[:k + 1] + ranges[-k:])             # ranges[0] is ahead, the end wraps round
        left = ranges[k + 1:side + 1]                          # counter-clockwise: left first
        right = ranges[-side:-k]
        cmd = Twist()
        if front < 0.8:
            if self.turning_ == 0.0:
                self.turning_ = 1.0 if sum(left) / len(left) > sum(right) / len(right) else -1.0
            cmd.linear.x = 0.2
            cmd.angular.z = 1.5 * self.turning_
        else:
            self.turning_ = 0.0
            cmd.linear.x = 1.0
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = ObstacleAvoiderNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
