# Wrong, but only just: watches the single beam ranges[0]. A turtle is a point,
# so it never quite hits anything, but it grazes past obstacles a few
# centimetres away: one beam sees a line, and a real robot is wider than that.
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
        ahead = scan.ranges[0]
        cmd = Twist()
        if math.isfinite(ahead) and ahead < 0.9:
            cmd.angular.z = 2.0
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
