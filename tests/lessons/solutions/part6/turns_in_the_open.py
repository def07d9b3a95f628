"""Wrong: the condition the wrong way round. It turns where it should race
(in the open: a small circle round its start, 60 m of it) and races where it
should turn (near a wall: into it). From the centre it never meets a wall."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, msg):
        cmd = Twist()
        if 2.0 < msg.x < 9.0 and 2.0 < msg.y < 9.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
        self.pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(TurtleControllerNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
