"""Right, another way: no callbacks at all. main() sends each goal and waits
for its result with spin_until_future_complete before sending the next
(allowed there: main() is not inside a callback)."""
import math

import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


class RotateClientNode(Node):
    def __init__(self):
        super().__init__("compass")
        self.client_ = ActionClient(self, RotateAbsolute, "/turtle1/rotate_absolute")

    def on_feedback(self, feedback_msg):
        self.get_logger().info(f"remaining {feedback_msg.feedback.remaining:.3f}")


def main(args=None):
    rclpy.init(args=args)
    node = RotateClientNode()
    node.client_.wait_for_server()
    for degrees in (90, 180, -90, 0):
        goal = RotateAbsolute.Goal()
        goal.theta = math.radians(degrees)
        sent = node.client_.send_goal_async(goal, feedback_callback=node.on_feedback)
        rclpy.spin_until_future_complete(node, sent)
        result = sent.result().get_result_async()
        rclpy.spin_until_future_complete(node, result)
        node.get_logger().info(f"facing {degrees} degrees")
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
