"""Right, another way: each target spawned with a name of its own choosing,
and the chase driven by the target's own pose topic."""
import math

import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose
from turtlesim.srv import Kill, Spawn

TARGETS_X = [8.0, 5.0, 2.5, 3.5, 7.0, 9.0, 6.5, 3.0]
TARGETS_Y = [7.5, 9.0, 6.5, 3.0, 2.5, 5.0, 6.0, 8.5]


class Hunter(Node):
    def __init__(self):
        super().__init__("hunter")
        self.declare_parameter("targets_x", TARGETS_X)
        self.declare_parameter("targets_y", TARGETS_Y)
        self.targets_ = list(zip(self.get_parameter("targets_x").value, self.get_parameter("targets_y").value))
        self.index_ = 0
        self.prey_ = None
        self.prey_pose_ = None
        self.prey_sub_ = None
        self.cmd_pub_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.spawn_ = self.create_client(Spawn, "/spawn")
        self.kill_ = self.create_client(Kill, "/kill")
        self.spawn_.wait_for_service()
        self.next_prey()

    def next_prey(self):
        if self.index_ == len(self.targets_):
            return
        x, y = self.targets_[self.index_]
        self.index_ += 1
        name = f"prey{self.index_}"
        self.spawn_.call_async(Spawn.Request(x=x, y=y, theta=0.0, name=name)).add_done_callback(self.on_spawned)

    def on_spawned(self, future):
        self.prey_ = future.result().name
        self.prey_pose_ = None
        if self.prey_sub_ is not None:
            self.destroy_subscription(self.prey_sub_)
        self.prey_sub_ = self.create_subscription(Pose, f"/{self.prey_}/pose", self.on_prey_pose, 10)

    def on_prey_pose(self, pose):
        self.prey_pose_ = pose

    def on_pose(self, pose):
        cmd = Twist()
        if self.prey_ is not None and self.prey_pose_ is not None:
            dx = self.prey_pose_.x - pose.x
            dy = self.prey_pose_.y - pose.y
            if math.hypot(dx, dy) < 0.3:
                self.kill_.call_async(Kill.Request(name=self.prey_)).add_done_callback(lambda f: self.next_prey())
                self.prey_ = None
            else:
                error = math.atan2(dy, dx) - pose.theta
                error = math.atan2(math.sin(error), math.cos(error))
                cmd.angular.z = 5.0 * error
                cmd.linear.x = 1.5 * math.hypot(dx, dy) if abs(error) < 0.5 else 0.0
        self.cmd_pub_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Hunter())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
