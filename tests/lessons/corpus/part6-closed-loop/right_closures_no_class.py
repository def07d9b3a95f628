"""Right: no class - rclpy.create_node and a closure over the publisher."""
import rclpy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


def make_callback(publisher, logger):
    def on_pose(pose):
        cmd = Twist()
        near_wall = pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0
        cmd.linear.x = 1.0 if near_wall else 5.0
        cmd.angular.z = 1.5 if near_wall else 0.0
        publisher.publish(cmd)

    return on_pose


def main():
    rclpy.init()
    node = rclpy.create_node("turtle_controller")
    publisher = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    node.create_subscription(Pose, "/turtle1/pose", make_callback(publisher, node.get_logger()), 10)
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
