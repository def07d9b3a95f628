"""Wrong: drives at a constant speed and never stops. With no tolerance the
turtle passes the goal, turns round, passes it again...: it circles the goal
for ever instead of stopping on it."""
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
        angle_to_goal = math.atan2(self.goal_y_ - pose.y, self.goal_x_ - pose.x)
        error = math.atan2(math.sin(angle_to_goal - pose.theta), math.cos(angle_to_goal - pose.theta))
        cmd = Twist()
        cmd.linear.x = 2.0
        cmd.angular.z = 4.0 * error
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(GoToGoalNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
