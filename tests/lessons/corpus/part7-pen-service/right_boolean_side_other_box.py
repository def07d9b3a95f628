"""Right, written differently: one client made in __init__, the side kept as
a boolean, another safe box and turn rate, and a done callback that logs."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import SetPen


class ColourByHalf(Node):
    def __init__(self):
        super().__init__("colour_by_half")
        self.on_right = None
        self.publisher = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.client = self.create_client(SetPen, "/turtle1/set_pen")
        self.client.wait_for_service()
        self.create_subscription(Pose, "/turtle1/pose", self.on_pose, 10)

    def on_pose(self, pose):
        cmd = Twist()
        if min(pose.x, pose.y) < 1.8 or max(pose.x, pose.y) > 9.3:
            cmd.linear.x = 1.2
            cmd.angular.z = 2.2
        else:
            cmd.linear.x = 3.5
        self.publisher.publish(cmd)
        right = pose.x > 5.5
        if right != self.on_right:
            self.on_right = right
            request = SetPen.Request()
            request.r, request.g, request.b = (200, 30, 30) if right else (30, 200, 30)
            request.width = 4
            self.client.call_async(request).add_done_callback(self.done)

    def done(self, future):
        self.get_logger().info("pen changed" if future.result() is not None else "pen call failed")


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(ColourByHalf())
    rclpy.shutdown()


if __name__ == "__main__":
    main()
