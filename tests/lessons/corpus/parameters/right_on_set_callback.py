"""Right: declare_parameters at once, values cached in attributes and updated by an on-set callback."""
import rclpy
from geometry_msgs.msg import Twist
from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from turtlesim.msg import Pose


class Avoider(Node):
    def __init__(self):
        super().__init__("avoider")
        self.declare_parameters("", [("speed", 5.0), ("slow_speed", 1.0), ("turn_rate", 1.5),
                                     ("box_min", 2.0), ("box_max", 9.0)])
        self.p = {name: self.get_parameter(name).value for name in
                  ("speed", "slow_speed", "turn_rate", "box_min", "box_max")}
        self.add_on_set_parameters_callback(self.on_set)
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_set(self, params):
        for param in params:
            self.p[param.name] = param.value
        return SetParametersResult(successful=True)

    def on_pose(self, pose):
        lo, hi = self.p["box_min"], self.p["box_max"]
        cmd = Twist()
        if not (lo <= pose.x <= hi and lo <= pose.y <= hi):
            cmd.linear.x = self.p["slow_speed"]
            cmd.angular.z = self.p["turn_rate"]
        else:
            cmd.linear.x = self.p["speed"]
        self.pub.publish(cmd)


def main():
    rclpy.init()
    rclpy.spin(Avoider())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
