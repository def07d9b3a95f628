"""Wrong: the timer is created after rclpy.spin(), which never returns: nothing is published."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class DrawCircleNode(Node):
    def __init__(self):
        super().__init__("draw_circle")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)

    def send(self):
        msg = Twist()
        msg.linear.x = 2.0
        msg.angular.z = 1.0
        self.pub.publish(msg)


def main():
    rclpy.init()
    node = DrawCircleNode()
    rclpy.spin(node)
    node.create_timer(0.5, node.send)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
