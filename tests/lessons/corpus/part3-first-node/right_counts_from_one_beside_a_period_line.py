import rclpy
from rclpy.node import Node

TIMER_PERIOD = 1.0


class FirstNode(Node):
    def __init__(self):
        super().__init__("first_node")
        self.count = 0
        self.timer = self.create_timer(TIMER_PERIOD, self.on_timer)
        self.get_logger().info(f"Timer started, period {TIMER_PERIOD}")

    def on_timer(self):
        self.count += 1
        self.get_logger().info(f"Hello world #{self.count}!")


def main(args=None):
    rclpy.init(args=args)
    node = FirstNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
