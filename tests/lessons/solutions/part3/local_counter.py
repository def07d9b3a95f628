"""Wrong: the counter is a local variable of the callback, so it starts again at 0
every time (Hello 1, Hello 1, Hello 1...)."""
import rclpy
from rclpy.node import Node


class MyNode(Node):
    def __init__(self):
        super().__init__("first_node")
        self.create_timer(1.0, self.timer_callback)

    def timer_callback(self):
        counter = 0
        counter += 1
        self.get_logger().info("Hello " + str(counter))


def main(args=None):
    rclpy.init(args=args)
    node = MyNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
