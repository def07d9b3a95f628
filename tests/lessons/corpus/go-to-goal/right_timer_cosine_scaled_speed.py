"""Right: a 10 Hz timer steers from the latest pose, speed scaled by cos(error), parameters read each time."""
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
        self.pose = None
        self.pub = self.create_publisher(Twist, "turtle1/cmd_vel", 10)
        self.sub = self.create_subscription(Pose, "turtle1/pose", self.save_pose, 10)
        self.timer = self.create_timer(0.1, self.control)

    def save_pose(self, msg):
        self.pose = msg

    def control(self):
        if self.pose is None:
            return
        gx = self.get_parameter("goal_x").get_parameter_value().double_value
        gy = self.get_parameter("goal_y").get_parameter_value().double_value
        dist = math.hypot(gx - self.pose.x, gy - self.pose.y)
        cmd = Twist()
        if dist > 0.05:
            err = math.atan2(gy - self.pose.y, gx - self.pose.x) - self.pose.theta
            err = (err + math.pi) % (2 * math.pi) - math.pi
            cmd.angular.z = 4.0 * err
            cmd.linear.x = max(0.0, math.cos(err)) * min(1.2 * dist, 2.5)
        self.pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = GoToGoalNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
