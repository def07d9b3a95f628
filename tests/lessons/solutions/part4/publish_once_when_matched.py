"""Wrong: waits until turtlesim has discovered its publisher, then publishes
one Twist and no more. turtlesim stops the turtle 1 s after that command: it
draws a short arc and stands still."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class DrawCircleNode(Node):
    def __init__(self):
        super().__init__("draw_circle")
        self.cmd_vel_pub_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)

    def send_velocity_command(self):
        msg = Twist()
        msg.linear.x = 2.0
        msg.angular.z = 1.0
        self.cmd_vel_pub_.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = DrawCircleNode()
    while node.cmd_vel_pub_.get_subscription_count() == 0:
        rclpy.spin_once(node, timeout_sec=0.01)
    node.send_velocity_command()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
