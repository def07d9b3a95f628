"""Wrong in ROS 2 too: awaiting call_async in a callback of the default (mutually exclusive) group never returns."""
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

    async def pose_callback(self, pose: Pose):
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
        self.cmd_vel_publisher_.publish(cmd)
        if pose.x > 5.5 and self.previous_x_ <= 5.5:
            self.previous_x_ = pose.x
            await self.client_.call_async(SetPen.Request(r=255, g=0, b=255, width=3, off=0))
        elif pose.x <= 5.5 and self.previous_x_ > 5.5:
            self.previous_x_ = pose.x
            await self.client_.call_async(SetPen.Request(r=0, g=255, b=255, width=3, off=0))


def main(args=None):
    rclpy.init(args=args)
    node = TurtleControllerNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
