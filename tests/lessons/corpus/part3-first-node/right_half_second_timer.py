"""Right, written differently: a 0.5 s timer, a counter from 1, other names,
and two log lines per tick (only the one ending with the counter counts)."""
import rclpy
from rclpy.node import Node


class Ticker(Node):
    def __init__(self):
        super().__init__("ticker")
        self.ticks = 1
        self.create_timer(0.5, self.tick)
        self.get_logger().info("ticker ready, one tick every half second")

    def tick(self):
        self.get_logger().debug("tick!")
        self.get_logger().info(f"Ticks so far: {self.ticks}.")
        self.ticks = self.ticks + 1


def main():
    rclpy.init()
    rclpy.spin(Ticker())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
