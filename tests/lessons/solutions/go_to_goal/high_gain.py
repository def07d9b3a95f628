"""Wrong: a huge linear gain and a small angular one. Far from the goal the
turtle races off at 10 x the distance while it is still turning round, and
runs into the wall before it faces the goal."""
import math

import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
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
        dx = self.goal_x_ - pose.x
        dy = self.goal_y_ - pose.y
        distance = math.sqrt(dx * dx + dy * dy)
        cmd = Twist()
        if distance > 0.05:
            angle_to_goal = math.atan2(dy, dx)
            error = math.atan2(math.sin(angle_to_goal - pose.theta), math.cos(angle_to_goal - pose.theta))
            cmd.linear.x = 10.0 * distance
            cmd.angular.z = 1.0 * error
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(GoToGoalNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
