"""Wrong: the angle to the goal in degrees minus pose.theta in radians."""
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
            error = math.degrees(math.atan2(dy, dx)) - pose.theta
            if error > 180:
                error -= 360
            elif error < -180:
                error += 360
            cmd.angular.z = 0.1 * error
            if abs(error) < 45:
                cmd.linear.x = min(1.5 * distance, 3.0)
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = GoToGoalNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
