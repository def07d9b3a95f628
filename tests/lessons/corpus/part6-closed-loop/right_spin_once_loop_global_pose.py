"""Right: no logic in the callback - it stores the pose in a global, and main steers in
its own loop after each spin_once."""
import rclpy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose

latest = None


def on_pose(msg):
    global latest
    latest = msg


def main():
    rclpy.init()
    node = rclpy.create_node("turtle_controller")
    pub = node.create_publisher(Twist, "/turtle1/cmd_vel", 10)
    node.create_subscription(Pose, "/turtle1/pose", on_pose, 10)
    while rclpy.ok():
        rclpy.spin_once(node)
        if latest is None:
            continue
        cmd = Twist()
        if latest.x > 9.0 or latest.x < 2.0 or latest.y > 9.0 or latest.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
        pub.publish(cmd)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
