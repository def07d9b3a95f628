"""Part 4 under a MultiThreadedExecutor: the timer callback sleeps after each command, so
the pose callback (another group) runs in the executor's other thread, where it fails once,
after about a second. As in ROS 2, spin() raises the error in main() and the node dies of it."""

import time

import rclpy
from geometry_msgs.msg import Twist
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from turtlesim.msg import Pose


class Circle(Node):
    def __init__(self):
        super().__init__("circle")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_timer(0.5, self.tick, callback_group=MutuallyExclusiveCallbackGroup())
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10, callback_group=MutuallyExclusiveCallbackGroup())
        self.speeds = []
        self.poses = 0

    def tick(self):
        msg = Twist()
        msg.linear.x = 2.0
        msg.angular.z = 1.0
        self.pub.publish(msg)
        time.sleep(0.3)  # "let the turtle move"

    def on_pose(self, pose):
        self.poses += 1
        if self.poses == 70:  # report once, after about a second
            self.get_logger().info(f"speed {self.speeds[-1]:.2f}")  # IndexError: nothing ever fills speeds


def main():
    rclpy.init()
    executor = MultiThreadedExecutor(num_threads=2)
    executor.add_node(Circle())
    executor.spin()


if __name__ == "__main__":
    main()
