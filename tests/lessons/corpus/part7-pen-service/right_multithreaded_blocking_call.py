"""Right: a blocking client.call() in the pose callback, made safe by a MultiThreadedExecutor and the client in its own callback group."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from turtlesim.msg import Pose
from turtlesim.srv import SetPen


class TurtleControllerNode(Node):
    def __init__(self):
        super().__init__("turtle_controller")
        self.cmd_vel_publisher_ = self.create_publisher(Twist, "/turtle1/cmd_vel", 10)
        self.create_subscription(Pose, "/turtle1/pose", self.pose_callback, 10)
        self.client_group_ = MutuallyExclusiveCallbackGroup()
        self.client_ = self.create_client(SetPen, "/turtle1/set_pen", callback_group=self.client_group_)
        self.client_.wait_for_service()
        self.previous_x_ = None

    def pose_callback(self, pose: Pose):
        cmd = Twist()
        if pose.x > 9.0 or pose.x < 2.0 or pose.y > 9.0 or pose.y < 2.0:
            cmd.linear.x = 1.0
            cmd.angular.z = 1.5
        else:
            cmd.linear.x = 5.0
        self.cmd_vel_publisher_.publish(cmd)
        if self.previous_x_ is None or (pose.x > 5.5) != (self.previous_x_ > 5.5):
            self.previous_x_ = pose.x
            colour = (255, 0, 0) if pose.x > 5.5 else (0, 255, 0)
            request = SetPen.Request(r=colour[0], g=colour[1], b=colour[2], width=3, off=0)
            self.client_.call(request)
            self.get_logger().info(f"pen set to {colour}")


def main(args=None):
    rclpy.init(args=args)
    node = TurtleControllerNode()
    executor = MultiThreadedExecutor()
    executor.add_node(node)
    executor.spin()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
