"""Right: waits for the service in __init__, side as the sign of x - 5.5, done callback via partial, drive in a timer."""
import math
from functools import partial

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import SetPen

SPLIT = 5.5
PENS = {1.0: (255, 0, 0), -1.0: (0, 0, 255)}


class PenBySide(Node):
    def __init__(self):
        super().__init__("pen_by_side")
        self.pose = None
        self.side = 0.0
        self.pub = self.create_publisher(Twist, "turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "turtle1/pose", self.on_pose, 10)
        self.pen = self.create_client(SetPen, "turtle1/set_pen")
        while not self.pen.wait_for_service(timeout_sec=1.0):
            self.get_logger().info("waiting for set_pen")
        self.create_timer(0.02, self.step)

    def on_pose(self, pose):
        self.pose = pose
        side = math.copysign(1.0, pose.x - SPLIT)
        if side != self.side:
            self.side = side
            r, g, b = PENS[side]
            future = self.pen.call_async(SetPen.Request(r=r, g=g, b=b, width=3, off=0))
            future.add_done_callback(partial(self.pen_done, side))

    def pen_done(self, side, future):
        future.result()
        self.get_logger().info(f"pen for side {side:+.0f}")

    def step(self):
        if self.pose is None:
            return
        p = self.pose
        near_wall = p.x < 2.0 or p.x > 9.0 or p.y < 2.0 or p.y > 9.0
        cmd = Twist()
        cmd.linear.x = 1.0 if near_wall else 5.0
        cmd.angular.z = 1.5 if near_wall else 0.0
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(PenBySide())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
