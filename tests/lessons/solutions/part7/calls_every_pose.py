"""Wrong: calls /turtle1/set_pen from every pose with the colour of the side the
turtle is on. The trail looks right, but that is 62.5 service calls a second."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import SetPen


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.pose_subscriber_ = self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.set_pen_client_ = self.create_client(SetPen, "/turtle1/set_pen")

    def pose_callback(self, pose: Pose):
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
            cmd.angular.z = 0.0
        self.cmd_vel_publisher_.publish(cmd)

        request = SetPen.Request()
        if pose.x > 5.5:
            request.r, request.g, request.b = 255, 0, 0
        else:
            request.r, request.g, request.b = 0, 255, 0
        request.width = 3
        future = self.set_pen_client_.call_async(request)
        future.add_done_callback(self.callback_set_pen)

    def callback_set_pen(self, future):
        try:
            future.result()
        except Exception as e:
            self.get_logger().error(f"Service call failed: {e!r}")


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(TurtleControllerNode())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
