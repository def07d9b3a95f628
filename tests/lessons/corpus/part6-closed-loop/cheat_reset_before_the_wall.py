"""Cheat: drives straight ahead and calls /reset whenever the turtle nears a
wall, which puts it back in the centre instead of steering."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_srvs.srv import Empty
from turtlesim.msg import Pose


class Resetter(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.reset_ = self.create_client(Empty, "/reset")
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose: Pose):
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            self.reset_.call_async(Empty.Request())
        cmd = Twist()
        cmd.linear.x = 5.0
        cmd.angular.z = 0.7
        self.publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Resetter())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
