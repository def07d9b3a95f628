"""A node that drives turtle1 in a square, open loop, from a timer.

Ordinary rclpy code: it runs unchanged against a real turtlesim
(``ros2 run`` it through a ``main()`` of your own). Each timer tick publishes
the velocity for the current leg; after enough ticks it switches between
driving straight and turning 90 degrees on the spot.
"""

import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

TICK = 0.1  # s between velocity commands
TURN_RATE = math.pi / 2  # rad/s: a quarter turn takes one second


class SquareDriver(Node):
    def __init__(self):
        super().__init__("square_driver")
        self.side_length = self.declare_parameter("side_length", 2.0).value  # m
        self.speed = self.declare_parameter("speed", 1.0).value  # m/s
        self.straight_ticks = max(1, round(self.side_length / self.speed / TICK))
        self.turn_ticks = max(1, round((math.pi / 2) / TURN_RATE / TICK))
        self.turning = False
        self.ticks_left = self.straight_ticks
        self.sides_done = 0
        self.cmd_vel_pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.timer = self.create_timer(TICK, self.on_tick)
        self.get_logger().info(f"Driving a square with {self.side_length:.1f} m sides")

    def on_tick(self):
        if self.ticks_left == 0:
            self.turning = not self.turning
            self.ticks_left = self.turn_ticks if self.turning else self.straight_ticks
            if self.turning:
                self.sides_done += 1
                self.get_logger().info(f"Side {self.sides_done} done, turning left")
        msg = Twist()
        if self.turning:
            msg.angular.z = TURN_RATE
        else:
            msg.linear.x = self.speed
        self.cmd_vel_pub.publish(msg)
        self.ticks_left -= 1


def main(args=None):
    rclpy.init(args=args)
    node = SquareDriver()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
