"""Wrong: the chase steers by the raw heading error (atan2 to the target minus theta),
never wrapped into [-pi, pi]: across the +-pi line the error is near 2 pi, and turtle1
turns the long way round (5.2-5.4 rad one way) to face the next target. It still
catches them, slower: it loses the points of the short turn."""
import math
from functools import partial

import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose
from turtlesim.srv import Kill, Spawn


# Where the targets appear, in order: the game decides, not the chaser.
TARGETS_X = [8.0, 5.0, 2.5, 3.5, 7.0, 9.0, 6.5, 3.0]
TARGETS_Y = [7.5, 9.0, 6.5, 3.0, 2.5, 5.0, 6.0, 8.5]


class TurtleChaserNode(Node):
    def __init__(self):
        super().__init__("turtle_chaser")
        self.declare_parameter("targets_x", TARGETS_X)
        self.declare_parameter("targets_y", TARGETS_Y)
        self.declare_parameter("catch_distance", 0.5)
        self.targets_ = list(zip(self.get_parameter("targets_x").value, self.get_parameter("targets_y").value))
        self.catch_distance_ = self.get_parameter("catch_distance").value
        self.target_ = None  # (name, x, y) of the turtle being chased
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.pose_subscriber_ = self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.spawn_client_ = self.create_client(Spawn, "/spawn")
        self.kill_client_ = self.create_client(Kill, "/kill")
        while not self.spawn_client_.wait_for_service(1.0):
            self.get_logger().warn("Waiting for the /spawn service...")
        self.spawn_target()

    def spawn_target(self):
        if not self.targets_:
            self.get_logger().info("Every target caught!")
            return
        request = Spawn.Request()
        request.x, request.y = self.targets_.pop(0)
        request.theta = 0.0
        request.name = ""  # turtlesim picks the next free turtleN
        future = self.spawn_client_.call_async(request)
        future.add_done_callback(partial(self.callback_spawn, x=request.x, y=request.y))

    def callback_spawn(self, future, x, y):
        name = future.result().name
        if name:
            self.target_ = (name, x, y)
            self.get_logger().info(f"Spawned {name} at ({x:.2f}, {y:.2f})")

    def pose_callback(self, pose: Pose):
        cmd = Twist()
        if self.target_ is not None:
            name, x, y = self.target_
            dx = x - pose.x
            dy = y - pose.y
            distance = math.sqrt(dx * dx + dy * dy)
            if distance < self.catch_distance_:
                self.target_ = None
                self.kill_turtle(name)
            else:
                angle_to_target = math.atan2(dy, dx)
                error = angle_to_target - pose.theta
                cmd.angular.z = 6.0 * error
                if abs(error) < math.pi / 4:
                    cmd.linear.x = min(2.0 * distance, 4.0)
        self.cmd_vel_publisher_.publish(cmd)

    def kill_turtle(self, name):
        request = Kill.Request()
        request.name = name
        future = self.kill_client_.call_async(request)
        future.add_done_callback(partial(self.callback_kill, name=name))

    def callback_kill(self, future, name):
        self.get_logger().info(f"Caught {name}!")
        self.spawn_target()


def main(args=None):
    rclpy.init(args=args)
    node = TurtleChaserNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
