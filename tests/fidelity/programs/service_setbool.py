"""A std_srvs/SetBool service and its client in one node (the official service tutorial's shape)."""
import rclpy
from rclpy.node import Node
from std_srvs.srv import SetBool, Trigger


class Switch(Node):
    def __init__(self):
        super().__init__("switch")
        self.state = False
        self.create_service(SetBool, "enable", self.on_enable)
        self.create_service(Trigger, "report", self.on_report)
        self.enable = self.create_client(SetBool, "enable")
        self.report = self.create_client(Trigger, "report")

    def on_enable(self, request, response):
        self.get_logger().info(f"request: data={request.data}")
        response.success = request.data != self.state
        response.message = "changed" if response.success else "already so"
        self.state = request.data
        return response

    def on_report(self, request, response):
        response.success = True
        response.message = f"state is {self.state}"
        return response


def main():
    rclpy.init()
    node = Switch()
    while not node.enable.wait_for_service(timeout_sec=1.0):
        node.get_logger().info("waiting for the service")
    node.report.wait_for_service(timeout_sec=5.0)
    for value in (True, True, False):
        future = node.enable.call_async(SetBool.Request(data=value))
        rclpy.spin_until_future_complete(node, future)
        result = future.result()
        print(f"SetBool({value}): success={result.success} message={result.message!r}")
    future = node.report.call_async(Trigger.Request())
    rclpy.spin_until_future_complete(node, future)
    print(future.result())
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
