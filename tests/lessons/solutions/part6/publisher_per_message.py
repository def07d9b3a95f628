"""Wrong: a new publisher in every pose callback. A publisher made just before it
publishes is not matched with turtlesim yet (DDS discovery takes a moment, on a real
ROS 2 graph too): every message is lost and the turtle never moves. The callback runs
and publishes, so "never published" would send the student looking in the wrong place."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.pose_subscriber_ = self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, pose: Pose):
        publisher = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
        publisher.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(TurtleControllerNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
