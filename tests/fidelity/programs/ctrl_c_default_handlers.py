"""Ctrl-C with rclpy's default signal handlers (rclpy.init() without
signal_handler_options): rclpy's SIGINT handler shuts the context down before
the KeyboardInterrupt, so rclpy.ok() is False in ``except KeyboardInterrupt``
and a last stop Twist published there fails; the program's own
rclpy.shutdown() still runs the on_shutdown callbacks (ros/joint_state_publisher#85,
bit-bots/bitbots_vision#344, ros2/rclpy#532). Sandboxed only: in-process, a
SIGINT is turtletui's own Ctrl-C, which ends the run (exit status 130)."""
import os
import signal

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Driver(Node):
    def __init__(self):
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.ticks = 0
        self.create_timer(0.1, self.drive)

    def drive(self):
        self.ticks += 1
        self.pub.publish(Twist())
        if self.ticks == 3:
            print("Ctrl-C", flush=True)
            os.kill(os.getpid(), signal.SIGINT)  # as Ctrl-C in the terminal


def main():
    rclpy.init()
    rclpy.get_default_context().on_shutdown(lambda: print("on_shutdown callback", flush=True))
    node = Driver()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        print("KeyboardInterrupt; rclpy.ok():", rclpy.ok(), "node.context.ok():", node.context.ok(), flush=True)
        try:
            node.pub.publish(Twist())
            print("stop Twist published", flush=True)
        except Exception as err:
            print("stop Twist:", type(err).__module__, type(err).__name__, err, flush=True)
        print("signal handlers:", rclpy.signals.get_current_signal_handlers_options(), flush=True)
    rclpy.shutdown()
    print("after rclpy.shutdown(): ok", rclpy.ok(), flush=True)
    print("handlers:", rclpy.signals.get_current_signal_handlers_options())


if __name__ == "__main__":
    main()
