"""Wrong: declares speed with an integer default (5, not 5.0). The parameter
is then an INTEGER, and ROS refuses -p speed:=2.0 (a DOUBLE): the node stops
with InvalidParameterTypeException as soon as it is given a speed."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.declare_parameter("speed", 5)
        self.declare_parameter("slow_speed", 1.0)
        self.declare_parameter("turn_rate", 1.5)
        self.declare_parameter("box_min", 2.0)
        self.declare_parameter("box_max", 9.0)
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, pose: Pose):
        box_min = self.get_parameter("box_min").value
        box_max = self.get_parameter("box_max").value
        cmd = Twist()
        if pose.x > box_max or pose.x < box_min or pose.y > box_max or pose.y < box_min:
            cmd.linear.x = self.get_parameter("slow_speed").value
            cmd.angular.z = self.get_parameter("turn_rate").value
        else:
            cmd.linear.x = float(self.get_parameter("speed").value)
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(TurtleControllerNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
