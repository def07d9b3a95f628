"""Right: a dict of colours by side, last side None so the first pose sets the colour, a pending flag."""
import time
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

        self.side_ = None
        self.colours_ = {"east": (200, 30, 30), "west": (30, 200, 30)}

    def pose_callback(self, pose):
        self.drive(pose)
        side = "east" if pose.x > 5.5 else "west"
        if side == self.side_:
            return
        self.side_ = side
        self.get_logger().info(f"now on the {side} side")
        future = self.set_pen(*self.colours_[side])
        future.add_done_callback(lambda f: self.get_logger().debug("pen set"))

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
