"""Right: each parameter declared with a descriptor, its value kept from declare_parameter in __init__."""
import rclpy
from geometry_msgs.msg import Twist
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node
from turtlesim.msg import Pose


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.speed = self.declare_parameter("speed", 5.0, ParameterDescriptor(description="m/s in the box")).value
        self.slow = self.declare_parameter("slow_speed", 1.0, ParameterDescriptor(description="m/s near walls")).value
        self.turn = self.declare_parameter("turn_rate", 1.5, ParameterDescriptor(description="rad/s")).value
        self.lo = self.declare_parameter("box_min", 2.0).value
        self.hi = self.declare_parameter("box_max", 9.0).value
        self.get_logger().info(f"speed={self.speed} slow={self.slow} turn={self.turn} box=[{self.lo}, {self.hi}]")
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose):
        inside = self.lo <= pose.x <= self.hi and self.lo <= pose.y <= self.hi
        cmd = Twist()
        cmd.linear.x = self.speed if inside else self.slow
        cmd.angular.z = 0.0 if inside else self.turn
        self.pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = TurtleControllerNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
