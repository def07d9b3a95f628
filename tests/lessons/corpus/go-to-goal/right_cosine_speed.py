"""Right, written differently: the forward speed scaled by the cosine of the
heading error (never backwards), a goal log line, another node name."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class Homing(Node):
    def __init__(self):
        super().__init__("homing")
        self.declare_parameter("goal_x", 8.0)
        self.declare_parameter("goal_y", 8.0)
        self.gx = self.get_parameter("goal_x").value
        self.gy = self.get_parameter("goal_y").value
        self.arrived = False
        self.publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.callback, 10)
        self.get_logger().info(f"heading for ({self.gx}, {self.gy})")

    def callback(self, pose):
        distance = math.hypot(self.gx - pose.x, self.gy - pose.y)
        twist = Twist()
        if distance > 0.05:
            error = math.remainder(math.atan2(self.gy - pose.y, self.gx - pose.x) - pose.theta, math.tau)
            twist.angular.z = 5.0 * error
            twist.linear.x = max(0.0, math.cos(error)) ** 3 * min(2.0 * distance, 3.0)
        elif not self.arrived:
            self.arrived = True
            self.get_logger().info("arrived")
        self.publisher_.publish(twist)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Homing())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
