"""Right: the timer callback logs through rclpy.logging.get_logger(name), not
the node's own logger; the line still comes from the callback."""
import rclpy
import rclpy.logging
from rclpy.node import Node

class MyNode(Node):
    def __init__(self):
        super().__init__("first_node")
        self.counter_ = 0
        self.timer_ = self.create_timer(1.0, self.timer_callback)

    def timer_callback(self):
        rclpy.logging.get_logger("first_node").info("Hello " + str(self.counter_))
        self.counter_ += 1

def main(args=None):
    rclpy.init(args=args)
    node = MyNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    node.destroy_node()
    rclpy.try_shutdown()

if __name__ == "__main__":
    main()
