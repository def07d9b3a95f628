"""Right: main() calls spin_once in a loop, and the timer's callback logs
(unlike spin_once_loop.py, where main() logs between the spins)."""
import rclpy
from rclpy.node import Node

class MyNode(Node):
    def __init__(self):
        super().__init__("first_node")
        self.counter_ = 0
        self.create_timer(1.0, self.timer_callback)

    def timer_callback(self):
        self.get_logger().info("Hello " + str(self.counter_))
        self.counter_ += 1

def main(args=None):
    rclpy.init(args=args)
    node = MyNode()
    while rclpy.ok():
        rclpy.spin_once(node, timeout_sec=0.1)
    rclpy.shutdown()

if __name__ == "__main__":
    main()
