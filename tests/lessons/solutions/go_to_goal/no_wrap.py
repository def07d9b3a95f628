"""Wrong: the heading error is never wrapped into [-pi, pi]. Everywhere but due
west that only turns the turtle the long way round; due west the angle to
the goal flips between +pi and -pi, the error jumps by 2 pi and the turtle
spins on the spot."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class GoToGoal(Node):
    def __init__(self):
        super().__init__("go_to_goal")
        self.goal = (self.declare_parameter("goal_x", 8.0).value, self.declare_parameter("goal_y", 8.0).value)
        self.pose = None
        self.done = False
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.create_timer(0.05, self.control)

    def on_pose(self, msg):
        self.pose = msg

    def control(self):
        if self.pose is None:
            return
        dx = self.goal[0] - self.pose.x
        dy = self.goal[1] - self.pose.y
        dist = math.hypot(dx, dy)
        cmd = Twist()
        if dist > 0.04:
            err = math.atan2(dy, dx) - self.pose.theta
            cmd.angular.z = 4.0 * err
            if abs(err) < 0.3:
                cmd.linear.x = min(2.0, 1.2 * dist)
        elif not self.done:
            self.done = True
            self.get_logger().info("Goal reached")
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(GoToGoal())


if __name__ == "__main__":
    main()
