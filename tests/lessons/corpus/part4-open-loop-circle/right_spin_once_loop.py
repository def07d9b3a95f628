"""Right, written differently: no timer but a loop in main() around
spin_once, turning clockwise (a negative angular.z)."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("loop_circle")
    publisher = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    command = Twist()
    command.linear.x = 2.5
    command.angular.z = -1.25
    while rclpy.ok():
        publisher.publish(command)
        rclpy.spin_once(node, timeout_sec=0.2)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
