"""executor.create_task() of a coroutine, and an async def subscription callback awaiting
client.call_async() for each message (its own task, in a Reentrant group)."""
import time

import rclpy
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future
from std_msgs.msg import Int32
from std_srvs.srv import SetBool


class Doubler(Node):
    def __init__(self):
        super().__init__("doubler")
        group = ReentrantCallbackGroup()
        self.create_service(SetBool, "check", self.on_check, callback_group=group)
        self.client = self.create_client(SetBool, "check", callback_group=group)
        self.create_subscription(Int32, "n", self.on_number, 10, callback_group=group)
        self.pub = self.create_publisher(Int32, "n", 10)
        self.answers = 0
        self.all_answered = Future()

    def on_check(self, request, response):
        response.success = request.data
        return response

    async def on_number(self, msg):
        answer = await self.client.call_async(SetBool.Request(data=msg.data % 2 == 0))
        self.get_logger().info(f"{msg.data} even: {answer.success}")
        self.answers += 1
        if self.answers == 3:
            self.all_answered.set_result(True)


async def publish_all(node):
    for n in range(3):
        node.pub.publish(Int32(data=n))
    return "published"


def main():
    rclpy.init()
    node = Doubler()
    time.sleep(1.0)  # discovery: the publisher and the subscription match
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    task = executor.create_task(publish_all, node)
    executor.spin_until_future_complete(task)
    node.get_logger().info(task.result())
    executor.spin_until_future_complete(node.all_answered, timeout_sec=5.0)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
