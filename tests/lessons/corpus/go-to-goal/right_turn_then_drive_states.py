"""Right: turn on the spot first, then drive and correct; a state machine with a 0.08 m tolerance."""
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
        self.state = "TURN"
        self.publisher = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, pose):
        goal_x = self.get_parameter("goal_x").value
        goal_y = self.get_parameter("goal_y").value
        dx, dy = goal_x - pose.x, goal_y - pose.y
        distance = math.hypot(dx, dy)
        error = math.atan2(dy, dx) - pose.theta
        while error > math.pi:
            error -= 2 * math.pi
        while error < -math.pi:
            error += 2 * math.pi
        cmd = Twist()
        if distance < 0.08:
            if self.state != "DONE":
                self.get_logger().info("Goal reached")
            self.state = "DONE"
        elif self.state == "DONE" or abs(error) > 0.5:
            self.state = "TURN"
        if self.state == "TURN":
            cmd.angular.z = 3.0 * error
            if abs(error) < 0.05:
                self.state = "DRIVE"
        elif self.state == "DRIVE":
            cmd.linear.x = min(2.0 * distance, 2.0)
            cmd.angular.z = 4.0 * error
        self.publisher.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = GoToGoalNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
