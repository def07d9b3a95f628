# Wrong: takes the middle of ranges as straight ahead, as on a scanner whose
# angle_min is -pi. Here angle_min is 0: ranges[0] is ahead and the middle of
# the list looks behind the turtle, so it watches its tail and hits what is in front.
import math

import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan


def closest(readings):
    valid = [r for r in readings if math.isfinite(r)]
    return min(valid) if valid else math.inf


class ObstacleAvoiderNode(Node):
    def __init__(self):
        super().__init__('obstacle_avoider')
        self.cmd_vel_publisher_ = self.create_publisher(Twist, '/turtle1/cmd_vel', 10)
        self.scan_subscriber_ = self.create_subscription(LaserScan, '/turtle1/scan', self.scan_callback, qos_profile_sensor_data)

    def scan_callback(self, scan: LaserScan):
        n = len(scan.ranges)
        middle = n // 2
        front = closest(scan.ranges[middle - 6:middle + 7])
        left = closest(scan.ranges[middle + 7:middle + 18])
        right = closest(scan.ranges[middle - 18:middle - 6])
        cmd = Twist()
        if front < 0.9:
            cmd.angular.z = 2.0 if left > right else -2.0
        else:
            cmd.linear.x = 1.5
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
