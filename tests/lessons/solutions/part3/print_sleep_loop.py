"""Wrong: print() and time.sleep in a loop of main(). The printed lines look
like a timer's log, but nothing logs them and nothing spins."""
import time

import rclpy
from rclpy.node import Node


def main(args=None):
    rclpy.init(args=args)
    Node("first_node")
    counter = 0
    while rclpy.ok():
        print("Hello", counter)
        counter += 1
        time.sleep(1.0)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
