"""Right: one client made in __init__, the side kept as None/"right"/"left", a done callback given the colour with partial."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import SetPen
from functools import partial


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.set_pen_client_ = self.create_client(SetPen, "/turtle1/set_pen")
        while not self.set_pen_client_.wait_for_service(timeout_sec=1.0):
            self.get_logger().info("waiting for /turtle1/set_pen")
        self.side_ = None

    def pose_callback(self, pose: Pose):
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
        self.cmd_vel_publisher_.publish(cmd)
        side = "right" if pose.x > 5.5 else "left"
        if side != self.side_:
            self.side_ = side
            if side == "right":
                self.set_pen(255, 0, 0)
            else:
                self.set_pen(0, 255, 0)

    def set_pen(self, r, g, b):
        request = SetPen.Request()
        request.r = r
        request.g = g
        request.b = b
        request.width = 3
        request.off = 0
        future = self.set_pen_client_.call_async(request)
        future.add_done_callback(partial(self.pen_done, r=r, g=g, b=b))

    def pen_done(self, future, r, g, b):
        try:
            future.result()
            self.get_logger().info(f"pen is now ({r}, {g}, {b})")
        except Exception as e:
            self.get_logger().error(f"set_pen failed: {e}")


def main(args=None):
    rclpy.init(args=args)
    node = TurtleControllerNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
