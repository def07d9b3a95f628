"""Right, another way: reads every parameter once, in __init__ (then
`ros2 param set` does not change it while it runs, but -p at start does)."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.speed_ = self.declare_parameter("speed", 5.0).value
        self.slow_speed_ = self.declare_parameter("slow_speed", 1.0).value
        self.turn_rate_ = self.declare_parameter("turn_rate", 1.5).value
        self.box_min_ = self.declare_parameter("box_min", 2.0).value
        self.box_max_ = self.declare_parameter("box_max", 9.0).value
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, pose: Pose):
        cmd = Twist()
        inside = self.box_min_ <= pose.x <= self.box_max_ and self.box_min_ <= pose.y <= self.box_max_
        if inside:
            cmd.linear.x = self.speed_
        else:
            cmd.linear.x = self.slow_speed_
            cmd.angular.z = self.turn_rate_
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(TurtleControllerNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
