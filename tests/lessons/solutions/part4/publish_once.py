"""Wrong: publishes one Twist from __init__, right after create_publisher, and
no more. turtlesim has not discovered the publisher yet, so the message is
lost, as on a real robot: the turtle never moves."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class DrawCircleNode(Node):
    def __init__(self):
        super().__init__("draw_circle")
        self.cmd_vel_pub_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        msg = Twist()
        msg.linear.x = 2.0
        msg.angular.z = 1.0
        self.cmd_vel_pub_.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = DrawCircleNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
