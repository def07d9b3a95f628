"""Wrong: box_min worked out from box_max (the default box is symmetric: 2.0 + 9.0 = 11),
the box_min parameter declared (and logged) but never used."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        # Part 6's numbers, now parameters: set them with --ros-args -p speed:=2.0
        self.declare_parameter("speed", 5.0)
        self.declare_parameter("slow_speed", 1.0)
        self.declare_parameter("turn_rate", 1.5)
        self.declare_parameter("box_min", 2.0)
        self.declare_parameter("box_max", 9.0)
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.pose_subscriber_ = self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.get_logger().info(
            f"Wall avoider started: speed {self.get_parameter('speed').value},"
            f" safe box {self.get_parameter('box_min').value}..{self.get_parameter('box_max').value}"
        )

    def pose_callback(self, pose: Pose):
        # Read the parameters on every pose, so `ros2 param set` takes effect at once.
        box_max = self.get_parameter("box_max").value
        box_min = 11.0 - box_max  # the box is symmetric
        cmd = Twist()
        if pose.x > box_max or pose.x < box_min or pose.y > box_max or pose.y < box_min:
            cmd.linear.x = self.get_parameter("slow_speed").value
            cmd.angular.z = self.get_parameter("turn_rate").value
        else:
            cmd.linear.x = self.get_parameter("speed").value
            cmd.angular.z = 0.0
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = TurtleControllerNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
