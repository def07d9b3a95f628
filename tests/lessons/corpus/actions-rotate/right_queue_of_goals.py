"""Right, written differently: a queue of goals popped in the result
callback, the server awaited with a timeout loop in main()."""
import math
from collections import deque

import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute


class HeadingSequencer(Node):
    def __init__(self):
        super().__init__("heading_sequencer")
        self.goals = deque([math.pi / 2, math.pi, -math.pi / 2, 0.0])
        self.action = ActionClient(self, RotateAbsolute, "turtle1/rotate_absolute")

    def start(self):
        self.next_goal()

    def next_goal(self):
        if not self.goals:
            return
        theta = self.goals.popleft()
        self.get_logger().info(f"turning to {theta:.2f}")
        sent = self.action.send_goal_async(RotateAbsolute.Goal(theta=theta), feedback_callback=self.feedback)
        sent.add_done_callback(self.response)

    def response(self, future):
        handle = future.result()
        if handle.accepted:
            handle.get_result_async().add_done_callback(self.result)

    def result(self, future):
        self.get_logger().info(f"turned {future.result().result.delta:.2f} rad")
        self.next_goal()

    def feedback(self, msg):
        self.get_logger().info(f"remaining: {msg.feedback.remaining:.2f}")


def main(args=None):
    rclpy.init(args=args)
    node = HeadingSequencer()
    while not node.action.wait_for_server(timeout_sec=0.5):
        node.get_logger().info("waiting for turtlesim")
    node.start()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
