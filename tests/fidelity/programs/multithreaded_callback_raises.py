"""An exception in a callback a MultiThreadedExecutor runs beside another: a service handler
raises while a timer callback waits for its answer (client.call with a timeout). spin() raises
the handler's error in the thread that spins; the waiting callback goes on until its timeout,
and the executor's shutdown() waits for it. A program that does not catch it dies of it."""
import rclpy
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from std_srvs.srv import SetBool


class Fragile(Node):
    def __init__(self):
        super().__init__("fragile")
        self.create_service(SetBool, "check", self.on_check, callback_group=ReentrantCallbackGroup())
        self.client = self.create_client(SetBool, "check", callback_group=MutuallyExclusiveCallbackGroup())
        self.asking = self.create_timer(0.1, self.ask, callback_group=MutuallyExclusiveCallbackGroup())
        self.beats = 0
        self.create_timer(0.05, self.beat, callback_group=MutuallyExclusiveCallbackGroup())
        self.outcome = "still waiting"

    def on_check(self, request, response):
        self.get_logger().info(f"checking {request.data}")
        raise ValueError(f"cannot check {request.data}")

    def ask(self):
        self.asking.cancel()
        self.get_logger().info("asking")
        try:
            response = self.client.call(SetBool.Request(data=True), timeout_sec=0.5)
            self.outcome = f"answered {response.success}"
        except TimeoutError:
            self.outcome = "no answer in time"
        self.get_logger().info(self.outcome)

    def beat(self):
        self.beats += 1  # keeps the executor busy: rclpy raises a worker's error at its next dispatch


def main():
    rclpy.init()
    node = Fragile()
    node.client.wait_for_service()
    executor = MultiThreadedExecutor(num_threads=4)
    executor.add_node(node)
    try:
        executor.spin()
        print("spin returned")
    except ValueError as err:
        print("spin raised:", type(err).__name__, err)
    executor.shutdown()
    print("after shutdown:", node.outcome)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
