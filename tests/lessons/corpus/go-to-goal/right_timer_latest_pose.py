"""Right, written differently: a 20 Hz timer steers from the latest pose with
other gains, a speed cap and another tolerance."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class GoalSeeker(Node):
    def __init__(self):
        super().__init__("goal_seeker")
        self.declare_parameter("goal_x", 8.0)
        self.declare_parameter("goal_y", 8.0)
        self.goal = (self.get_parameter("goal_x").value, self.get_parameter("goal_y").value)
        self.pose = None
        self.cmd_pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.create_timer(0.05, self.control)

    def on_pose(self, pose):
        self.pose = pose

    def control(self):
        if self.pose is None:
            return
        dx, dy = self.goal[0] - self.pose.x, self.goal[1] - self.pose.y
        distance = math.hypot(dx, dy)
        cmd = Twist()
        if distance > 0.04:
            error = math.atan2(dy, dx) - self.pose.theta
            error = math.atan2(math.sin(error), math.cos(error))
            cmd.angular.z = 4.0 * error
            if abs(error) < 0.5:
                cmd.linear.x = min(1.2 * distance, 2.5)
        self.cmd_pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(GoalSeeker())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
