"""Right, another idiom: create_rate in a thread beside spin, Twist built once with keyword args."""
import threading
import rclpy
from geometry_msgs.msg import Twist, Vector3
from rclpy.node import Node


def main():
    rclpy.init()
    node = Node("circle_rate")
    pub = node.create_publisher(Twist, "turtle1/cmd_vel", 10)
    twist = Twist(linear=Vector3(x=1.8, y=0.0, z=0.0), angular=Vector3(z=0.9))
    spinner = threading.Thread(target=rclpy.spin, args=(node,), daemon=True)
    spinner.start()
    rate = node.create_rate(5)
    while rclpy.ok():
        pub.publish(twist)
        rate.sleep()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
