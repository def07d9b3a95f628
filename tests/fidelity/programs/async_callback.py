"""An async def timer callback awaiting client.call_async() (rclpy runs it as a task that
holds its callback group until it ends, so the service and client are in a Reentrant group)."""
import rclpy
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.node import Node
from rclpy.task import Future
from std_srvs.srv import SetBool


class Asker(Node):
    def __init__(self):
        super().__init__("asker")
        self.create_service(SetBool, "toggle", self.on_toggle, callback_group=ReentrantCallbackGroup())
        self.client = self.create_client(SetBool, "toggle", callback_group=ReentrantCallbackGroup())
        self.timer = self.create_timer(0.1, self.tick)
        self.count = 0
        self.finished = Future()

    def on_toggle(self, request, response):
        self.get_logger().info(f"serving {request.data}")
        response.success = request.data
        response.message = "on" if request.data else "off"
        return response

    async def tick(self):
        self.count += 1
        count = self.count
        self.get_logger().info(f"tick {count}: calling")
        response = await self.client.call_async(SetBool.Request(data=count % 2 == 1))
        self.get_logger().info(f"tick {count}: got {response.message}")
        if count == 3:
            self.timer.cancel()
            self.finished.set_result(count)


def main():
    rclpy.init()
    node = Asker()
    rclpy.spin_until_future_complete(node, node.finished)
    print("finished:", node.finished.result())
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
