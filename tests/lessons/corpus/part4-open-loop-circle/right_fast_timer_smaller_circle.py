"""Right, written differently: a 1.5 m circle, published ten times a second."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class CircleDriver(Node):
    def __init__(self):
        super().__init__("circle_driver")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.1, self.drive)
        self.get_logger().info("driving a circle of radius 1.5 m")

    def drive(self):
        twist = Twist()
        twist.linear.x = 1.5
        twist.angular.z = 1.0
        self.pub.publish(twist)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(CircleDriver())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
