"""Right, written differently: a 20 Hz timer reads the parameters and the
latest pose."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class TunableAvoider(Node):
    def __init__(self):
        super().__init__("tunable_avoider")
        for name, default in (("speed", 5.0), ("slow_speed", 1.0), ("turn_rate", 1.5), ("box_min", 2.0), ("box_max", 9.0)):
            self.declare_parameter(name, default)
        self.pose = None
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.keep, 10)
        self.create_timer(0.05, self.loop)

    def keep(self, pose):
        self.pose = pose

    def param(self, name):
        return self.get_parameter(name).value

    def loop(self):
        if self.pose is None:
            return
        low, high = self.param("box_min"), self.param("box_max")
        cmd = Twist()
        if not (low <= self.pose.x <= high and low <= self.pose.y <= high):
            cmd.linear.x = self.param("slow_speed")
            cmd.angular.z = self.param("turn_rate")
        else:
            cmd.linear.x = self.param("speed")
        self.pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(TunableAvoider())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
