"""Wrong: go to goal with the heading error wrapped on one side only (e > pi), not
below -pi: due west, where atan2 flips between +pi and -pi, an error near
-2 pi spins the turtle a full turn on the spot before it drives on."""

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
        self.declare_parameter("tolerance", 0.05)
        self.goal_x_ = self.get_parameter("goal_x").value
        self.goal_y_ = self.get_parameter("goal_y").value
        self.tolerance_ = self.get_parameter("tolerance").value
        self.reached_ = False
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.pose_subscriber_ = self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.get_logger().info(f"Going to ({self.goal_x_:.2f}, {self.goal_y_:.2f})")

    def pose_callback(self, pose: Pose):
        dx = self.goal_x_ - pose.x
        dy = self.goal_y_ - pose.y
        distance = math.sqrt(dx * dx + dy * dy)
        cmd = Twist()
        if distance > self.tolerance_:
            # the heading error, wrapped to [-pi, pi] so the turtle turns the short way
            angle_to_goal = math.atan2(dy, dx)
            error = angle_to_goal - pose.theta
            if error > math.pi:
                error -= 2 * math.pi
            cmd.angular.z = 6.0 * error
            if abs(error) < math.pi / 4:
                # only drive forward once roughly facing the goal
                cmd.linear.x = min(1.5 * distance, 3.0)
            self.reached_ = False
        elif not self.reached_:
            self.reached_ = True
            self.get_logger().info(f"Goal reached: ({pose.x:.2f}, {pose.y:.2f})")
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = GoToGoalNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
