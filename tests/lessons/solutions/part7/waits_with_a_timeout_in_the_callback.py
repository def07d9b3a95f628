"""Wrong: waits for each set_pen answer with spin_until_future_complete(timeout_sec=1.0)
inside the pose callback. The answer is in the callback's own (default, mutually
exclusive) group, so it cannot arrive before the callback returns: every wait lasts
its full second, during which no pose is handled and no velocity is sent."""
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
        self.client_.wait_for_service(timeout_sec=5.0)
        self.previous_x_ = 0.0

    def pose_callback(self, pose: Pose):
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
        self.cmd_vel_publisher_.publish(cmd)
        if pose.x > 5.5 and self.previous_x_ <= 5.5:
            self.previous_x_ = pose.x
            self.set_pen(255, 0, 0)
        elif pose.x <= 5.5 and self.previous_x_ > 5.5:
            self.previous_x_ = pose.x
            self.set_pen(0, 255, 0)

    def set_pen(self, r, g, b):
        future = self.client_.call_async(SetPen.Request(r=r, g=g, b=b, width=3, off=0))
        rclpy.spin_until_future_complete(self, future, timeout_sec=1.0)


def main(args=None):
    rclpy.init(args=args)
    node = TurtleControllerNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
