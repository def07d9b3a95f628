"""What a node's publishers, subscriptions, clients, services and timers list:
rclpy's own (/parameter_events, the parameter and type description services,
a rate's timer) beside the program's, and after some are destroyed."""

import rclpy
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Empty


def name_of(entity):
    return getattr(entity, "topic_name", None) or getattr(entity, "srv_name", None) or type(entity).__name__


def show(node, when):
    for kind in ("publishers", "subscriptions", "clients", "services", "timers"):
        print(when, kind, [name_of(e) for e in getattr(node, kind)])


def main():
    rclpy.init()
    node = Node("lister")
    show(node, "fresh")
    pub = node.create_publisher(String, "chatter", 10)
    node.create_subscription(String, "chatter", lambda msg: None, 10)
    timer = node.create_timer(1.0, lambda: None)
    node.create_rate(2.0)
    node.create_client(Empty, "clear")
    node.create_service(Empty, "~/ping", lambda request, response: response)
    show(node, "made")
    node.destroy_publisher(pub)
    node.destroy_timer(timer)
    show(node, "destroyed")
    print("a generator:", type(node.publishers).__name__)
    node.destroy_node()
    show(node, "node destroyed")
    rclpy.shutdown()


if __name__ == "__main__":
    main()
