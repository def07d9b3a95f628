"""A synchronous client.call() inside a timer callback, the official way: the client in a
callback group of its own, the service in a Reentrant one, a MultiThreadedExecutor."""
import rclpy
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future
from std_srvs.srv import SetBool


class Adder(Node):
    def __init__(self):
        super().__init__("adder")
        self.create_service(SetBool, "toggle", self.on_toggle, callback_group=ReentrantCallbackGroup())
        self.client = self.create_client(SetBool, "toggle", callback_group=MutuallyExclusiveCallbackGroup())
        self.finished = Future()
        self.timer = self.create_timer(0.1, self.tick)
        self.count = 0

    def on_toggle(self, request, response):
        response.success = request.data
        response.message = f"call {self.count}"
        return response

    def tick(self):
        self.count += 1
        response = self.client.call(SetBool.Request(data=self.count % 2 == 1))
        self.get_logger().info(f"tick {self.count}: success={response.success} message={response.message!r}")
        if self.count == 3:
            self.timer.cancel()
            self.finished.set_result(self.count)


def main():
    rclpy.init()
    node = Adder()
    node.client.wait_for_service()
    executor = MultiThreadedExecutor()
    executor.add_node(node)
    executor.spin_until_future_complete(node.finished)
    print("done after", node.finished.result(), "ticks")
    executor.shutdown()
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
