"""Wrong in its own way: a 10 Hz timer reacts 0.5 m late at 5 m/s and, turning right, circles outside the top of the box at slow speed."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.declare_parameter("speed", 5.0)
        self.declare_parameter("slow_speed", 1.0)
        self.declare_parameter("turn_rate", 1.5)
        self.declare_parameter("box_min", 2.0)
        self.declare_parameter("box_max", 9.0)
        self.pose = None
        self.pub = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.store_pose, 10)
        self.create_timer(0.1, self.loop)

    def store_pose(self, msg):
        self.pose = msg

    def loop(self):
        if self.pose is None:
            return
        speed, slow, turn, lo, hi = (
            p.get_parameter_value().double_value
            for p in self.get_parameters(["speed", "slow_speed", "turn_rate", "box_min", "box_max"])
        )
        x, y = self.pose.x, self.pose.y
        cmd = Twist()
        if min(x, y) < lo or max(x, y) > hi:
            cmd.linear.x = slow
            cmd.angular.z = -turn
        else:
            cmd.linear.x = speed
        self.pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = TurtleControllerNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
