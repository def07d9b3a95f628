"""Wrong: the topic misspelt (/turtle/cmd_vel). ROS 2 raises no error: the
Twists go to a topic nobody subscribes to, and the turtle never moves."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class DrawCircleNode(Node):
    def __init__(self):
        super().__init__("draw_circle")
        self.cmd_vel_pub_ = self.create_publisher(Twist, "/turtle/cmd_vel", 10)
        self.create_timer(0.5, self.send_velocity_command)

    def send_velocity_command(self):
        msg = Twist()
        msg.linear.x = 2.0
        msg.angular.z = 1.0
        self.cmd_vel_pub_.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(DrawCircleNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
