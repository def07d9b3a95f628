"""Stands in for the tutorial's teleop: drives turtle1 round a circle."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Circler(Node):
    def __init__(self):
        super().__init__('teleop_stand_in')
        self.publisher = self.create_publisher(Twist, '/turtle1/cmd_vel', 1)
        self.timer = self.create_timer(0.5, self.drive)

    def drive(self):
        msg = Twist()
        msg.linear.x = 1.0
        msg.angular.z = 0.5
        self.publisher.publish(msg)


def main():
    rclpy.init()
    rclpy.spin(Circler())
