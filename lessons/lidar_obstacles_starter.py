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
        # Sensor data QoS (best effort), as LiDAR drivers publish: a default (reliable)
        # subscription receives nothing from a best-effort publisher on a real robot.
        self.scan_subscriber_ = self.create_subscription(
            LaserScan, '/turtle1/scan', self.scan_callback, qos_profile_sensor_data
        )
        self.get_logger().info("Obstacle avoider has started: watching /turtle1/scan")

    def scan_callback(self, scan: LaserScan):
        # Keep the readings between range_min and range_max: that leaves out inf
        # (nothing in range), -inf (too close), nan (lost) and a real driver's 0.0.
        valid = [r for r in scan.ranges if scan.range_min <= r <= scan.range_max]
        closest = min(valid) if valid else math.inf
        self.get_logger().info(
            f"{len(scan.ranges)} beams, closest reading {closest:.2f} m", throttle_duration_sec=1.0
        )

        # TODO 1: beam i points at scan.angle_min + i * scan.angle_increment radians,
        #         counter-clockwise from straight ahead. Find the closest valid
        #         reading in the front sector (say 30 degrees either side).
        # TODO 2: do the same for a sector on the left and one on the right.
        # TODO 3: if the front is clear, drive forward; if something is closer
        #         than a threshold (say 0.9 m), stop and turn toward the side
        #         with more room until the front is clear again.
        cmd = Twist()
        cmd.linear.x = 0.3  # creeps forward, blind: it WILL hit something
        cmd.angular.z = 0.0
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
