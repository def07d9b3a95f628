"""Wrong: a 10 Hz timer sets the pen by the side of the latest x, every tick, changed or not."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import SetPen


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.client_ = self.create_client(SetPen, "/turtle1/set_pen")
        self.client_.wait_for_service()
        self.x_ = 5.5
        self.create_timer(0.1, self.update_pen)

    def pose_callback(self, pose: Pose):
        self.x_ = pose.x
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
        self.cmd_vel_publisher_.publish(cmd)

    def update_pen(self):
        rgb = (255, 0, 0) if self.x_ > 5.5 else (0, 255, 0)
        self.client_.call_async(SetPen.Request(r=rgb[0], g=rgb[1], b=rgb[2], width=3, off=0))


def main(args=None):
    rclpy.init(args=args)
    node = TurtleControllerNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
