"""Wrong, though it looks right: a 2.5..8.5 box with a tight clockwise turn (radius 0.5 m).
From the corner start (8.8, 8.8), already outside its box, the turn never brings the turtle
back in (its circle, 1 m across, stays beyond 8.5 on one axis or the other): it goes round in
circles there to the end."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose

LOW, HIGH = 2.5, 8.5


class WallAvoider(Node):
    def __init__(self):
        super().__init__("wall_avoider")
        self.publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose):
        msg = Twist()
        if not (LOW < pose.x < HIGH and LOW < pose.y < HIGH):
            msg.linear.x = 1.0
            msg.angular.z = -2.0
        else:
            msg.linear.x = 3.0
        self.publisher_.publish(msg)


def main():
    rclpy.init()
    node = WallAvoider()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
