"""Right, written differently: a while loop in main() that publishes and sleeps 0.1 s,
never spinning (a node that only publishes needs no executor)."""
import time

import rclpy
from geometry_msgs.msg import Twist


def main():
    rclpy.init()
    node = rclpy.create_node("loop_publisher")
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    cmd = Twist()
    cmd.linear.x = 1.5
    cmd.angular.z = 1.0
    while rclpy.ok():
        pub.publish(cmd)
        time.sleep(0.1)


if __name__ == "__main__":
    main()
