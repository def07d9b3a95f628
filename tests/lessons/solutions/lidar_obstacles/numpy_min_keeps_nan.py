"""Skips inf and -inf but not nan, and takes each sector's minimum with numpy:
one lost beam makes the minimum nan, and nan < 0.9 is False, so the turtle
drives on blind whenever a beam in front is lost."""

import math

import numpy as np

import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan

FRONT_HALF_WIDTH = math.radians(30)  # the front sector: 30 degrees either side of straight ahead
SIDE_WIDTH = math.radians(60)        # each side sector: from 30 to 90 degrees off the heading
STOP_DISTANCE = 0.9                  # metres: closer than this in front, turn away
CLEAR_DISTANCE = 1.3                 # metres: turn until the front is this clear
CRUISE_SPEED = 1.5                   # m/s
TURN_SPEED = 2.0                     # rad/s


class ObstacleAvoiderNode(Node):
    def __init__(self):
        super().__init__('obstacle_avoider')
        self.cmd_vel_publisher_ = self.create_publisher(Twist, '/turtle1/cmd_vel', 10)
        # Sensor data QoS (best effort), as LiDAR drivers publish: a default (reliable)
        # subscription receives nothing from a best-effort publisher on a real robot.
        self.scan_subscriber_ = self.create_subscription(
            LaserScan, '/turtle1/scan', self.scan_callback, qos_profile_sensor_data
        )
        self.turn_direction_ = 0.0  # 0: driving; +1 turning left; -1 turning right
        self.get_logger().info("Obstacle avoider has started: watching /turtle1/scan")

    def closest_in_sector(self, scan: LaserScan, low: float, high: float) -> float:
        """The closest valid reading between the angles low and high (radians, 0 = straight ahead)."""
        readings = []
        for i, r in enumerate(scan.ranges):
            angle = scan.angle_min + i * scan.angle_increment
            angle = math.atan2(math.sin(angle), math.cos(angle))  # into [-pi, pi]
            if not low <= angle <= high:
                continue
            if math.isinf(r):
                continue
            readings.append(r)
        return float(np.min(readings)) if readings else scan.range_max

    def scan_callback(self, scan: LaserScan):
        front = self.closest_in_sector(scan, -FRONT_HALF_WIDTH, FRONT_HALF_WIDTH)
        left = self.closest_in_sector(scan, FRONT_HALF_WIDTH, FRONT_HALF_WIDTH + SIDE_WIDTH)
        right = self.closest_in_sector(scan, -FRONT_HALF_WIDTH - SIDE_WIDTH, -FRONT_HALF_WIDTH)

        cmd = Twist()
        if self.turn_direction_ == 0.0 and front < STOP_DISTANCE:
            # pick a side once and keep it until the way is clear: no dithering left-right
            self.turn_direction_ = 1.0 if left >= right else -1.0
            side = "left" if self.turn_direction_ > 0 else "right"
            self.get_logger().info(f"Obstacle {front:.2f} m ahead: turning {side}")
        elif self.turn_direction_ != 0.0 and front > CLEAR_DISTANCE:
            self.turn_direction_ = 0.0

        if self.turn_direction_ != 0.0:
            cmd.linear.x = 0.0
            cmd.angular.z = TURN_SPEED * self.turn_direction_
        else:
            cmd.linear.x = CRUISE_SPEED
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
