"""Right: rclpy.spin runs in a thread of its own while main() joins it."""
import threading
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
    t = threading.Thread(target=rclpy.spin, args=(node,), daemon=True)
    t.start()
    t.join()
    rclpy.shutdown()

if __name__ == "__main__":
    main()
