"""Wrong: linear.x from dx, not from the distance: the turtle backs away from goals to its left."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class GoToGoalNode(Node):
    def __init__(self):
        super().__init__("go_to_goal")
        self.declare_parameter("goal_x", 8.0)
        self.declare_parameter("goal_y", 8.0)
        self.goal_x_ = self.get_parameter("goal_x").value
        self.goal_y_ = self.get_parameter("goal_y").value
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, pose: Pose):
        cmd = Twist()
        dx = self.goal_x_ - pose.x
        dy = self.goal_y_ - pose.y
        distance = math.sqrt(dx * dx + dy * dy)
        if distance > 0.05:
            error = math.atan2(dy, dx) - pose.theta
            error = math.atan2(math.sin(error), math.cos(error))
            cmd.angular.z = 6.0 * error
            cmd.linear.x = 1.5 * dx
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = GoToGoalNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
