"""Right: brisk gains, and once within the tolerance it stops for good (a
latch: it never looks at the pose again). It is at a near goal within about
1.3 s, so a teleport must come before that to be one on its way."""
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
        self.reached_ = False
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, pose: Pose):
        if self.reached_:
            return
        cmd = Twist()
        dx, dy = self.goal_x_ - pose.x, self.goal_y_ - pose.y
        distance = math.hypot(dx, dy)
        if distance > 0.05:
            error = math.atan2(dy, dx) - pose.theta
            error = math.atan2(math.sin(error), math.cos(error))
            cmd.angular.z = 8.0 * error
            if abs(error) < 0.5:
                cmd.linear.x = min(4.0 * distance, 4.0)
        else:
            self.reached_ = True
            self.get_logger().info("Goal reached")
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(GoToGoalNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
