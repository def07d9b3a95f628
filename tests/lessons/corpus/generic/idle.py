"""Degenerate: a node that does nothing at all (it only spins)."""

import rclpy
from rclpy.node import Node


def main(args=None):
    rclpy.init(args=args)
    node = Node("idle")
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
