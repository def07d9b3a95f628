# Wrong: treats a reading of inf ("nothing within range_max") as 0 ("touching"),
# so open space looks blocked and the turtle spins in place looking for a wall.
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

    def scan_callback(self, scan: LaserScan):
        ranges = [r if math.isfinite(r) else 0.0 for r in scan.ranges]
        front = min(ranges[:7] + ranges[-6:])
        left = min(ranges[7:19])
        right = min(ranges[-18:-6])
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
