#!/usr/bin/env python3
"""Part 4 starter: an open-loop publisher. Make the turtle draw a circle.

Run it with:  turtletui run part4_starter.py
(or on a real ROS 2 turtlesim:  python3 part4_starter.py)
"""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class DrawCircleNode(Node):
    def __init__(self):
        super().__init__("draw_circle")
        self.cmd_vel_pub_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        # TODO 1: create a timer that calls self.send_velocity_command every
        #         0.5 s (turtlesim stops the turtle 1 s after the last command).
        self.get_logger().info("Draw circle node has been started")

    def send_velocity_command(self):
        msg = Twist()
        # TODO 2: set msg.linear.x (forward speed, m/s) and msg.angular.z
        #         (turn rate, rad/s). The circle's radius is linear.x / angular.z.
        # Until you fill these in, msg stays all zeros: the turtle sits still.
        self.cmd_vel_pub_.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = DrawCircleNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
