"""Wrong: splits the arena at x = 5.0 ("the middle") instead of 5.5.
Each way across, the colour changes half a metre from the line: whole-run shares
of poses hardly see it, every crossing does."""
from functools import partial

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import SetPen


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.previous_x_ = 0.0
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.pose_subscriber_ = self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.pen_client_ = self.create_client(SetPen, "/turtle1/set_pen")

    def pose_callback(self, pose):
        self.drive(pose)
        if pose.x > 5.0 and self.previous_x_ <= 5.0:
            self.set_pen(255, 0, 0)
        elif pose.x <= 5.0 and self.previous_x_ > 5.0:
            self.set_pen(0, 255, 0)
        self.previous_x_ = pose.x

    def drive(self, pose):
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
            cmd.angular.z = 0.0
        self.cmd_vel_publisher_.publish(cmd)

    def set_pen(self, r, g, b):
        request = SetPen.Request()
        request.r = r
        request.g = g
        request.b = b
        request.width = 3
        request.off = 0
        return self.pen_client_.call_async(request)


def main(args=None):
    rclpy.init(args=args)
    node = TurtleControllerNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
