"""Right: get_parameter_value().double_value, a 50 Hz timer on the latest pose, a ParameterDescriptor."""
import rclpy
from geometry_msgs.msg import Twist
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node
from turtlesim.msg import Pose


class Avoider(Node):
    NAMES = ("speed", "slow_speed", "turn_rate", "box_min", "box_max")

    def __init__(self):
        super().__init__("typed_avoider")
        for name, default in zip(self.NAMES, (5.0, 1.0, 1.5, 2.0, 9.0)):
            self.declare_parameter(name, default, ParameterDescriptor(description=name))
        self.pose = None
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", lambda p: setattr(self, "pose", p), 10)
        self.create_timer(0.02, self.step)

    def value(self, name):
        return self.get_parameter(name).get_parameter_value().double_value

    def step(self):
        if self.pose is None:
            return
        p = self.pose
        lo, hi = self.value("box_min"), self.value("box_max")
        cmd = Twist()
        if min(p.x, p.y) < lo or max(p.x, p.y) > hi:
            cmd.linear.x = self.value("slow_speed")
            cmd.angular.z = self.value("turn_rate")
        else:
            cmd.linear.x = self.value("speed")
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(Avoider())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
