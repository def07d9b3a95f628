"""A node that writes to stdout and to stderr (print(..., file=sys.stderr), a warning, rclpy's
DeprecationWarning for logger.warn) and leaves with sys.exit(0) in a timer callback: stderr
stays stderr, SystemExit goes out of rclpy.spin, the program ends with status 0 and the line
after spin never runs."""
import sys
import warnings

import rclpy
from rclpy.node import Node


class Leaver(Node):
    def __init__(self):
        super().__init__("leaver")
        self.n = 0
        self.create_timer(0.2, self.tick)

    def tick(self):
        self.n += 1
        print(f"out {self.n}", flush=True)
        print(f"err {self.n}", file=sys.stderr, flush=True)
        if self.n == 1:
            warnings.warn("careful", stacklevel=1)
            self.get_logger().warn("old warn")
        if self.n == 3:
            sys.exit(0)


def main():
    rclpy.init()
    rclpy.spin(Leaver())
    print("after spin")


if __name__ == "__main__":
    main()
