"""Wrong: the timer is on a second node that nothing spins, so it never fires (as in ROS 2)."""
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
    helper = Node("helper")
    node = MyNode()
    rclpy.spin(helper)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
