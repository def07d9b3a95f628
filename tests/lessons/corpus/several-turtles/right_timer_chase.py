"""Right, written differently: a 20 Hz timer chases from the latest pose,
other gains, targets kept as an index into the parameter lists."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import Kill, Spawn


class Catcher(Node):
    def __init__(self):
        super().__init__("catcher")
        self.declare_parameter("targets_x", [8.0, 5.0, 2.5, 3.5, 7.0, 9.0, 6.5, 3.0])
        self.declare_parameter("targets_y", [7.5, 9.0, 6.5, 3.0, 2.5, 5.0, 6.0, 8.5])
        self.xs = self.get_parameter("targets_x").value
        self.ys = self.get_parameter("targets_y").value
        self.next = 0
        self.prey = None  # (name, x, y)
        self.pose = None
        self.cmd = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.spawner = self.create_client(Spawn, "/spawn")
        self.killer = self.create_client(Kill, "/kill")
        self.create_timer(0.05, self.chase)
        self.spawner.wait_for_service()
        self.spawn_next()

    def spawn_next(self):
        if self.next >= len(self.xs):
            return
        x, y = self.xs[self.next], self.ys[self.next]
        self.next += 1
        future = self.spawner.call_async(Spawn.Request(x=x, y=y, theta=0.0, name=""))
        future.add_done_callback(lambda f: self.spawned(f, x, y))

    def spawned(self, future, x, y):
        self.prey = (future.result().name, x, y)
        self.get_logger().info(f"chasing {self.prey[0]}")

    def on_pose(self, pose):
        self.pose = pose

    def chase(self):
        cmd = Twist()
        if self.pose is not None and self.prey is not None:
            name, x, y = self.prey
            distance = math.hypot(x - self.pose.x, y - self.pose.y)
            if distance < 0.4:
                self.prey = None
                self.killer.call_async(Kill.Request(name=name)).add_done_callback(lambda f: self.spawn_next())
            else:
                error = math.atan2(y - self.pose.y, x - self.pose.x) - self.pose.theta
                error = math.atan2(math.sin(error), math.cos(error))
                cmd.angular.z = 5.0 * error
                cmd.linear.x = min(1.8 * distance, 3.5) if abs(error) < 0.7 else 0.0
        self.cmd.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Catcher())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
