"""Wrong: reads the pose once, plans the turn and the drive from it, then runs
the plan by the clock. From an undisturbed start it arrives; when anything
moves the turtle on the way it drives on as planned and misses the goal."""
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
        self.plan_ = None
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.create_timer(0.016, self.drive)

    def pose_callback(self, pose: Pose):
        if self.plan_ is None:
            dx, dy = self.goal_x_ - pose.x, self.goal_y_ - pose.y
            turn = math.atan2(math.sin(math.atan2(dy, dx) - pose.theta), math.cos(math.atan2(dy, dx) - pose.theta))
            start = self.get_clock().now().nanoseconds / 1e9
            self.plan_ = (start, turn, math.hypot(dx, dy))

    def drive(self):
        cmd = Twist()
        if self.plan_ is not None:
            start, turn, distance = self.plan_
            elapsed = self.get_clock().now().nanoseconds / 1e9 - start
            turning = abs(turn) / 1.0
            if elapsed < turning:
                cmd.angular.z = math.copysign(1.0, turn)
            elif elapsed < turning + distance / 1.0:
                cmd.linear.x = 1.0
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(GoToGoalNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
