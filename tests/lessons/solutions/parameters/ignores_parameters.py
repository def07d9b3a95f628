"""Wrong: declares the parameters but never reads them: the numbers in
pose_callback are still Part 6's constants, so -p speed:=2.0 changes nothing."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.declare_parameter("speed", 5.0)
        self.declare_parameter("slow_speed", 1.0)
        self.declare_parameter("turn_rate", 1.5)
        self.declare_parameter("box_min", 2.0)
        self.declare_parameter("box_max", 9.0)
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, pose: Pose):
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(TurtleControllerNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
