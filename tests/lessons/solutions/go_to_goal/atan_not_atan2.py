"""Wrong: math.atan(dy / dx) instead of math.atan2(dy, dx). atan only returns
angles between -90 and +90 degrees, so for a goal to the left (dx < 0) the
turtle heads the opposite way, and straight above or below it (dx == 0) the
division fails."""
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
            error = math.atan(dy / dx) - pose.theta
            error = math.atan2(math.sin(error), math.cos(error))
            cmd.angular.z = 6.0 * error
            if abs(error) < math.pi / 4:
                cmd.linear.x = min(1.5 * distance, 3.0)
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(GoToGoalNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
