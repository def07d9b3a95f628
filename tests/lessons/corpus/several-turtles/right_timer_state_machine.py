"""Right, written differently: a 20 Hz timer runs a state machine (SPAWN, WAIT, CHASE,
KILLING), relative service and topic names, lambdas as done callbacks."""
import math

import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose
from turtlesim.srv import Kill, Spawn


class Hunter(Node):
    """A 20 Hz timer drives a small state machine: SPAWN -> WAIT -> CHASE -> KILLING."""

    def __init__(self):
        super().__init__("hunter")
        self.declare_parameter("targets_x", [8.0, 5.0, 2.5, 3.5, 7.0, 9.0, 6.5, 3.0])
        self.declare_parameter("targets_y", [7.5, 9.0, 6.5, 3.0, 2.5, 5.0, 6.0, 8.5])
        xs = self.get_parameter("targets_x").get_parameter_value().double_array_value
        ys = self.get_parameter("targets_y").get_parameter_value().double_array_value
        self.queue = list(zip(xs, ys))
        self.state = "SPAWN"
        self.prey = None
        self.me = None
        self.pub = self.create_publisher(Twist, "turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "turtle1/pose", self.on_pose, 10)
        self.spawn_cli = self.create_client(Spawn, "spawn")
        self.kill_cli = self.create_client(Kill, "kill")
        self.spawn_cli.wait_for_service()
        self.kill_cli.wait_for_service()
        self.create_timer(0.05, self.step)

    def on_pose(self, msg):
        self.me = msg

    def step(self):
        cmd = Twist()
        if self.state == "SPAWN" and self.queue:
            x, y = self.queue.pop(0)
            req = Spawn.Request(x=float(x), y=float(y), theta=0.0, name="")
            self.state = "WAIT"
            self.spawn_cli.call_async(req).add_done_callback(lambda f: self.spawned(f, x, y))
        elif self.state == "CHASE" and self.me is not None:
            name, x, y = self.prey
            dist = math.hypot(x - self.me.x, y - self.me.y)
            if dist < 0.4:
                self.state = "KILLING"
                self.kill_cli.call_async(Kill.Request(name=name)).add_done_callback(self.killed)
            else:
                heading = math.atan2(y - self.me.y, x - self.me.x)
                err = (heading - self.me.theta + math.pi) % (2 * math.pi) - math.pi
                cmd.angular.z = 5.0 * err
                cmd.linear.x = min(3.0, 1.5 * dist) * max(0.0, math.cos(err))
        self.pub.publish(cmd)

    def spawned(self, future, x, y):
        self.prey = (future.result().name, x, y)
        self.state = "CHASE"

    def killed(self, _future):
        self.get_logger().info(f"caught {self.prey[0]}")
        self.state = "SPAWN"


def main():
    rclpy.init()
    rclpy.spin(Hunter())


if __name__ == "__main__":
    main()
