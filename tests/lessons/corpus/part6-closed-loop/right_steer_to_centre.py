"""Right, another way: near the walls it steers toward the arena's centre
with a proportional controller instead of turning at a fixed rate, and it
logs what it does."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose

CENTRE = 5.544445


class Keeper(Node):
    def __init__(self):
        super().__init__("keeper")
        self.publisher = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.subscription = self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)
        self.turning = False

    def on_pose(self, pose: Pose):
        twist = Twist()
        near_wall = min(pose.x, pose.y, 11.09 - pose.x, 11.09 - pose.y) < 2.5
        if near_wall:
            heading = math.atan2(CENTRE - pose.y, CENTRE - pose.x)
            error = math.atan2(math.sin(heading - pose.theta), math.cos(heading - pose.theta))
            twist.angular.z = 4.0 * error
            twist.linear.x = 0.8 if abs(error) > 0.6 else 2.5
            if not self.turning:
                self.get_logger().info(f"near a wall at ({pose.x:.1f}, {pose.y:.1f}): steering back")
        else:
            twist.linear.x = 3.0
        self.turning = near_wall
        self.publisher.publish(twist)


def main():
    rclpy.init()
    rclpy.spin(Keeper())


if __name__ == "__main__":
    main()
