"""Wrong: a 0.5 s timer whose callback sleeps 2 s after publishing: the turtle
drives 1 s and stands 1 s, over and over."""
import time

import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class DrawCircleNode(Node):
    def __init__(self):
        super().__init__("draw_circle")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.5, self.send)

    def send(self):
        msg = Twist()
        msg.linear.x = 2.0
        msg.angular.z = 1.0
        self.pub.publish(msg)
        time.sleep(2.0)  # wait before the next command


def main():
    rclpy.init()
    rclpy.spin(DrawCircleNode())


if __name__ == "__main__":
    main()
