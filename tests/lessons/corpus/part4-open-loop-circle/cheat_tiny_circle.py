"""Cheat: a "circle" of radius 5 cm, from a timer: spinning in place with a
little forward speed."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class DrawCircleNode(Node):
    def __init__(self):
        super().__init__("draw_circle")
        self.cmd_vel_pub_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.5, self.send_velocity_command)

    def send_velocity_command(self):
        msg = Twist()
        msg.linear.x = 0.1
        msg.angular.z = 2.0
        self.cmd_vel_pub_.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(DrawCircleNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
