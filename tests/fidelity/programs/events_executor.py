"""rclpy.experimental.EventsExecutor (Kilted) used as a student swaps it in for the
SingleThreadedExecutor: a timer that publishes, a subscription, a service and its client,
spin_until_future_complete, spin_once with a timeout, shutdown, and the executor's type."""
import rclpy
from rclpy.experimental import EventsExecutor
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Trigger


class Pinger(Node):
    def __init__(self):
        super().__init__("pinger")
        self.heard = []
        self.pub = self.create_publisher(String, "ping", 10)
        self.sub = self.create_subscription(String, "ping", self.on_ping, 10)
        self.srv = self.create_service(Trigger, "count", self.on_count)
        self.count = 0
        self.timer = self.create_timer(0.1, self.on_timer)

    def on_timer(self):
        if self.pub.get_subscription_count() == 0 or len(self.heard) < self.count:
            return
        self.pub.publish(String(data=f"ping {self.count}"))
        self.count += 1

    def on_ping(self, msg):
        self.get_logger().info(f"heard {msg.data}")
        self.heard.append(msg.data)

    def on_count(self, request, response):
        response.success = True
        response.message = f"{len(self.heard)} heard"
        return response


def main():
    rclpy.init()
    node = Pinger()
    executor = EventsExecutor()
    print("executor:", type(executor).__name__, "added:", executor.add_node(node))
    while len(node.heard) < 3:
        executor.spin_once(timeout_sec=1.0)
    node.timer.cancel()
    client = node.create_client(Trigger, "count")
    client.wait_for_service(timeout_sec=5.0)
    future = client.call_async(Trigger.Request())
    executor.spin_until_future_complete(future, timeout_sec=5.0)
    print("answer:", future.result().message)
    print("nodes:", [n.get_name() for n in executor.get_nodes()])
    executor.shutdown()
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
