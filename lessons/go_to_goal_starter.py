#!/usr/bin/env python3
"""Go-to-goal starter: drive turtle1 to (goal_x, goal_y) and stop there.

Run it with:  turtletui run go_to_goal_starter.py --ros-args -p goal_x:=2.0 -p goal_y:=6.0
(or on a real ROS 2 turtlesim:  python3 go_to_goal_starter.py --ros-args -p goal_x:=2.0)
"""

import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class GoToGoalNode(Node):
    def __init__(self):
        super().__init__("go_to_goal")
        # The goal is a pair of parameters: set them with --ros-args -p goal_x:=2.0
        self.declare_parameter("goal_x", 8.0)
        self.declare_parameter("goal_y", 8.0)
        self.goal_x_ = self.get_parameter("goal_x").value
        self.goal_y_ = self.get_parameter("goal_y").value
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.pose_subscriber_ = self.create_subscription(
            Pose, "/turtle1/pose", self.pose_callback, 10
        )
        self.get_logger().info(f"Going to ({self.goal_x_:.2f}, {self.goal_y_:.2f})")

    def pose_callback(self, pose: Pose):
        cmd = Twist()
        dx = self.goal_x_ - pose.x
        dy = self.goal_y_ - pose.y
        distance = math.sqrt(dx * dx + dy * dy)
        if distance > 0.05:
            # TODO 1: the angle to the goal: math.atan2(dy, dx) - not math.atan(dy / dx).
            # TODO 2: the heading error: that angle minus pose.theta, wrapped
            #         into [-pi, pi] with math.atan2(math.sin(e), math.cos(e)).
            # TODO 3: a P controller: cmd.angular.z = K_ANGULAR * heading error,
            #         cmd.linear.x = K_LINEAR * distance (try 6.0 and 1.5, at most
            #         3 m/s), and no forward speed until the heading error is small.
            pass
        else:
            # TODO 4: within the tolerance, cmd stays zero: the turtle stops.
            #         Log "Goal reached" - once.
            pass
        # Until you fill these in, cmd stays all zeros: the turtle sits still.
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = GoToGoalNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == "__main__":
    main()
