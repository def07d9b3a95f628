"""Wrong: turn_rate declared as "turning_rate": -p turn_rate:=3.0 sets nothing, the turtle turns at 1.5 rad/s."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.declare_parameter("speed", 5.0)
        self.declare_parameter("slow_speed", 1.0)
        self.declare_parameter("turning_rate", 1.5)
        self.declare_parameter("box_min", 2.0)
        self.declare_parameter("box_max", 9.0)
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)

    def pose_callback(self, pose: Pose):
        speed = self.get_parameter("speed").value
        slow_speed = self.get_parameter("slow_speed").value
        turn_rate = self.get_parameter("turning_rate").value
        box_min = self.get_parameter("box_min").value
        box_max = self.get_parameter("box_max").value
        cmd = Twist()
        if pose.x > box_max or pose.x < box_min or pose.y > box_max or pose.y < box_min:
            cmd.linear.x = slow_speed
            cmd.angular.z = turn_rate
        else:
            cmd.linear.x = speed
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = TurtleControllerNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
