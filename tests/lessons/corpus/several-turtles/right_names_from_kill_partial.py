"""Right, written differently: the targets popped from a list of (x, y)
pairs, functools.partial for the done callbacks, a smaller catch distance."""
import math
from functools import partial

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import Kill, Spawn


class Hunter(Node):
    def __init__(self):
        super().__init__("hunter")
        self.declare_parameter("targets_x", [8.0, 5.0, 2.5, 3.5, 7.0, 9.0, 6.5, 3.0])
        self.declare_parameter("targets_y", [7.5, 9.0, 6.5, 3.0, 2.5, 5.0, 6.0, 8.5])
        xs = self.get_parameter("targets_x").value
        ys = self.get_parameter("targets_y").value
        self.todo = [(x, y) for x, y in zip(xs, ys)]
        self.current = None
        self.caught = 0
        self.publisher = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.spawn_client = self.create_client(Spawn, "/spawn")
        self.kill_client = self.create_client(Kill, "/kill")
        while not self.spawn_client.wait_for_service(timeout_sec=1.0):
            pass
        self.spawn()

    def spawn(self):
        if self.todo:
            x, y = self.todo.pop(0)
            request = Spawn.Request()
            request.x, request.y = x, y
            self.spawn_client.call_async(request).add_done_callback(partial(self.on_spawn, x=x, y=y))

    def on_spawn(self, future, x, y):
        self.current = {"name": future.result().name, "x": x, "y": y}

    def pose_callback(self, pose):
        twist = Twist()
        target = self.current
        if target is not None:
            dx, dy = target["x"] - pose.x, target["y"] - pose.y
            if math.hypot(dx, dy) < 0.3:
                self.current = None
                request = Kill.Request()
                request.name = target["name"]
                self.kill_client.call_async(request).add_done_callback(partial(self.on_kill, name=target["name"]))
            else:
                error = math.remainder(math.atan2(dy, dx) - pose.theta, math.tau)
                twist.angular.z = 7.0 * error
                if abs(error) < 0.4:
                    twist.linear.x = min(2.5 * math.hypot(dx, dy), 4.5)
        self.publisher.publish(twist)

    def on_kill(self, future, name):
        self.caught += 1
        self.get_logger().info(f"caught {name} ({self.caught} so far)")
        self.spawn()


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Hunter())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
