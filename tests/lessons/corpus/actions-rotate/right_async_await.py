"""Right: async/await in a timer callback: await each goal handle and its result, the
client in a callback group of its own (in the node's default group, with the timer
that awaits, its answers could never be taken: see the wrong async_await_in_the_default_group)."""
import math
import time

import rclpy
from rclpy.action import ActionClient
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.node import Node
from turtlesim.action import RotateAbsolute

HEADINGS = {"north": math.pi / 2, "west": math.pi, "south": -math.pi / 2, "east": 0.0}


class RotateClientNode(Node):
    def __init__(self):
        super().__init__("compass")
        self.client = ActionClient(
            self, RotateAbsolute, "/turtle1/rotate_absolute", callback_group=ReentrantCallbackGroup()
        )
        self.timer = self.create_timer(0.2, self.run)

    async def run(self):
        self.timer.cancel()
        if not self.client.wait_for_server(timeout_sec=5.0):
            self.get_logger().error("no server")
            return
        for name, theta in HEADINGS.items():
            handle = await self.client.send_goal_async(
                RotateAbsolute.Goal(theta=theta),
                feedback_callback=lambda m: self.get_logger().info(f"Remaining {m.feedback.remaining:.2f}"))
            if not handle.accepted:
                return
            result = await handle.get_result_async()
            self.get_logger().info(f"facing {name}, delta {result.result.delta:.2f}")


def main(args=None):
    rclpy.init(args=args)
    node = RotateClientNode()
    rclpy.spin(node)
    rclpy.shutdown()


if __name__ == "__main__":
    main()
