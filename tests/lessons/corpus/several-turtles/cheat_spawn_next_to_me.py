"""Cheat: never moves turtle1; spawns each target half a metre from it and
kills it at once."""
# corpus: sandboxed
import math

import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import Kill, Spawn


class Cheater(Node):
    def __init__(self):
        super().__init__("turtle_chaser")
        self.pose_ = None
        self.busy_ = False
        self.spawn_ = self.create_client(Spawn, "/spawn")
        self.kill_ = self.create_client(Kill, "/kill")
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose: Pose):
        self.pose_ = pose
        if not self.busy_:
            self.busy_ = True
            request = Spawn.Request()
            request.x = pose.x + 0.5 * math.cos(pose.theta)
            request.y = pose.y + 0.5 * math.sin(pose.theta)
            self.spawn_.call_async(request).add_done_callback(self.on_spawned)

    def on_spawned(self, future):
        self.kill_.call_async(Kill.Request(name=future.result().name)).add_done_callback(self.on_killed)

    def on_killed(self, future):
        self.busy_ = False


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Cheater())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
