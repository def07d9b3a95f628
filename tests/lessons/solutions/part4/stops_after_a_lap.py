"""Wrong: stops publishing motion after one lap (7 s), sending zero Twists instead."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class DrawCircleNode(Node):
    def __init__(self):
        super().__init__("draw_circle")
        self.cmd_vel_pub_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.timer_ = self.create_timer(0.5, self.send_velocity_command)
        self.step = 0

    def send_velocity_command(self):
        msg = Twist()
        self.step += 1
        if self.step <= 14:  # one lap is 6.3 s
            msg.linear.x = 2.0
            msg.angular.z = 1.0
        self.cmd_vel_pub_.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(DrawCircleNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
