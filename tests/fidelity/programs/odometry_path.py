"""nav_msgs Odometry and Path: built, published, received and read field by field."""
import math

import rclpy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry, Path
from rclpy.node import Node


class Odom(Node):
    def __init__(self):
        super().__init__("odom_demo")
        self.odom_pub = self.create_publisher(Odometry, "odom", 10)
        self.path_pub = self.create_publisher(Path, "path", 10)
        self.create_subscription(Odometry, "odom", self.on_odom, 10)
        self.create_subscription(Path, "path", self.on_path, 10)
        self.done = 0

    def send(self):
        odom = Odometry()
        odom.header.frame_id = "odom"
        odom.child_frame_id = "base_link"
        odom.pose.pose.position.x = 1.5
        odom.pose.pose.orientation.z = math.sin(0.25)
        odom.pose.pose.orientation.w = math.cos(0.25)
        odom.twist.twist.linear.x = 0.5
        odom.pose.covariance[0] = 0.01
        self.odom_pub.publish(odom)
        path = Path()
        path.header.frame_id = "map"
        for i in range(3):
            pose = PoseStamped()
            pose.pose.position.x = float(i)
            path.poses.append(pose)
        self.path_pub.publish(path)

    def on_odom(self, msg):
        q = msg.pose.pose.orientation
        yaw = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
        self.get_logger().info(
            f"odom {msg.header.frame_id}->{msg.child_frame_id} x={msg.pose.pose.position.x} "
            f"yaw={yaw:.3f} v={msg.twist.twist.linear.x} cov0={msg.pose.covariance[0]}"
        )
        self.done += 1

    def on_path(self, msg):
        self.get_logger().info(f"path in {msg.header.frame_id}: {[p.pose.position.x for p in msg.poses]}")
        self.done += 1


def main():
    rclpy.init()
    node = Odom()
    while node.odom_pub.get_subscription_count() == 0 or node.path_pub.get_subscription_count() == 0:
        rclpy.spin_once(node, timeout_sec=0.1)
    node.send()
    while node.done < 2:
        rclpy.spin_once(node, timeout_sec=1.0)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
