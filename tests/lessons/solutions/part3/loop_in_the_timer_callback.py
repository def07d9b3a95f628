"""Wrong: the timer callback never returns: it loops, logs and sleeps a second,
so the timer is only a way to start a loop, and the executor is stuck in it."""
import time

import rclpy
from rclpy.node import Node


class MyNode(Node):
    def __init__(self):
        super().__init__("first_node")
        self.counter_ = 0
        self.create_timer(1.0, self.timer_callback)

    def timer_callback(self):
        while rclpy.ok():
            self.get_logger().info("Hello " + str(self.counter_))
            self.counter_ += 1
            time.sleep(1.0)


def main(args=None):
    rclpy.init(args=args)
    node = MyNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
