# Wrong: reads the front sector correctly and stops short of every obstacle,
# but never turns away, so it stands still in front of the first one forever.
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
        front = scan.ranges[:7] + scan.ranges[-6:]  # 30 degrees either side of ahead
        valid = [r for r in front if math.isfinite(r)]
        cmd = Twist()
        if not valid or min(valid) > 0.9:
            cmd.linear.x = 1.5
        # else: a zero Twist, stop and wait for the obstacle to go away
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
