"""What a MultiThreadedExecutor runs at the same time: a callback waiting for an event that
another callback sets gets it when the two are in different groups, and waits in vain when
they share a mutually exclusive group. Sandboxed only: threads need turtletui's sandbox."""
import threading

import rclpy
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future


class Waiter(Node):
    def __init__(self, name, same_group):
        super().__init__(name)
        first = MutuallyExclusiveCallbackGroup()
        second = first if same_group else ReentrantCallbackGroup()
        self.event = threading.Event()
        self.finished = Future()
        self.waiting = self.create_timer(0.1, self.wait_for_event, callback_group=first)
        self.setting = self.create_timer(0.3, self.set_event, callback_group=second)

    def wait_for_event(self):
        self.waiting.cancel()
        got = self.event.wait(timeout=1.0)
        self.get_logger().info("event set by the other callback" if got else "timed out waiting")

    def set_event(self):
        self.setting.cancel()
        self.get_logger().info("setting the event")
        self.event.set()
        self.finished.set_result(True)


def main():
    rclpy.init()
    for name, same_group in (("apart", False), ("together", True)):
        node = Waiter(name, same_group)
        executor = MultiThreadedExecutor(num_threads=2)
        executor.add_node(node)
        executor.spin_until_future_complete(node.finished)
        executor.spin_once(timeout_sec=0.5)
        executor.shutdown()
        node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
