"""Callbacks with the wrong number of parameters, as students write them: a subscription
callback without the msg parameter or with three (refused when made), one with a second
parameter that has a default (called with the message only), a timer callback that takes two,
a service callback that takes only the request; what rclpy raises, by type and message. (A
timer given a call's result, None, is left out: Kilted's executor fails on it with an
UnboundLocalError of its own that other distros do not share.)"""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Trigger


class Mistakes(Node):
    def __init__(self):
        super().__init__("mistakes")
        self.pub = self.create_publisher(String, "words", 10)
        try:
            self.create_subscription(String, "words", self.no_msg, 10)
        except Exception as err:
            print("subscription without msg:", type(err).__name__, err)
        try:
            self.create_subscription(String, "words", lambda a, b, c: None, 10)
        except Exception as err:
            print("subscription with three:", type(err).__name__, err)
        self.sub = self.create_subscription(String, "words", self.one_default, 10)

    def one_default(self, msg, extra=None):
        print("one_default ran with", msg.data, extra)

    def no_msg(self):
        print("no_msg ran")

    def two_args(self, a, b):
        print("two_args ran")

    def request_only(self, request):
        print("request_only ran")
        return Trigger.Response()


def spin_a_few(node, label):
    for _ in range(10):
        try:
            rclpy.spin_once(node, timeout_sec=0.1)
        except Exception as err:
            print(label, "raised", type(err).__name__, err)
            return


def main():
    rclpy.init()
    node = Mistakes()
    while node.pub.get_subscription_count() == 0:
        rclpy.spin_once(node, timeout_sec=0.05)
    node.pub.publish(String(data="hello"))
    spin_a_few(node, "subscription")
    node.destroy_subscription(node.sub)

    timer = node.create_timer(0.05, node.two_args)
    spin_a_few(node, "timer with two parameters")
    node.destroy_timer(timer)

    node.create_service(Trigger, "only_request", node.request_only)
    client = node.create_client(Trigger, "only_request")
    client.wait_for_service(timeout_sec=5.0)
    future = client.call_async(Trigger.Request())
    spin_a_few(node, "service")
    print("client answered:", future.done())

    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
