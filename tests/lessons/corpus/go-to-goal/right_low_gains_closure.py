"""Right: no class, a closure as the pose callback, low gains (2.5 and 0.9)."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


def main():
    rclpy.init()
    node = Node("go_to_goal")
    node.declare_parameter("goal_x", 8.0)
    node.declare_parameter("goal_y", 8.0)
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)

    def on_pose(pose):
        gx = node.get_parameter("goal_x").value
        gy = node.get_parameter("goal_y").value
        d = math.hypot(gx - pose.x, gy - pose.y)
        e = math.atan2(gy - pose.y, gx - pose.x) - pose.theta
        e = math.atan2(math.sin(e), math.cos(e))
        t = Twist()
        if d >= 0.05:
            t.angular.z = 2.5 * e
            t.linear.x = 0.9 * d if abs(e) < 0.3 else 0.0
        pub.publish(t)

    node.create_subscription(Pose, "/turtle1/pose", on_pose, 10)
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
