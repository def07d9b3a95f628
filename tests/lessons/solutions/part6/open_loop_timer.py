"""Wrong: publishes from a timer, whatever the pose (an open loop, as Part 4)."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class Driver(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.timer_ = self.create_timer(0.5, self.send)

    def send(self):
        cmd = Twist()
        cmd.linear.x = 2.0
        cmd.angular.z = 0.3
        self.cmd_vel_publisher_.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Driver())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
