"""Right, another idiom: parameters for the speeds, a lambda timer, relative topic name via a remappable name."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Circle(Node):
    def __init__(self):
        super().__init__("circle")
        self.declare_parameter("radius", 1.2)
        self.declare_parameter("turn_rate", -1.5)
        self.publisher = self.create_publisher(Twist, "/turtle1/cmd_vel", 1)
        self.timer = self.create_timer(0.25, lambda: self.publisher.publish(self.command()))

    def command(self) -> Twist:
        w = self.get_parameter("turn_rate").value
        cmd = Twist()
        cmd.angular.z = w
        cmd.linear.x = abs(w) * self.get_parameter("radius").value
        return cmd


def main():
    rclpy.init()
    node = Circle()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
