"""Mistakes in create_publisher, create_subscription, create_service and create_client arguments
that course code makes: the qos argument forgotten, given as a string, a float or a negative
depth, a message instance instead of its class, a class that is not a message, a service
class for a topic and a message class for a service, a topic of None, and a publisher's and
subscription's qos_profile made from a depth. (A depth of 0 is left out: rclpy's warning
about it is a line of rclpy's own, which the harness leaves out, and turtletui's is not.)"""
import rclpy
from rclpy.node import Node
from rclpy.qos import QoSProfile
from std_msgs.msg import String
from std_srvs.srv import Trigger


def attempt(label, action):
    try:
        print(label, action())
    except Exception as err:
        print(label, "->", type(err).__name__, str(err).split(", at ")[0])  # not rcl's source location


def main():
    rclpy.init()
    node = Node("arguments")
    attempt("publisher without qos:", lambda: node.create_publisher(String, "a"))
    attempt("subscription without qos:", lambda: node.create_subscription(String, "a", print))
    attempt("qos '10':", lambda: node.create_publisher(String, "a", "10"))
    attempt("qos 10.0:", lambda: node.create_publisher(String, "a", 10.0))
    attempt("qos -1:", lambda: node.create_publisher(String, "a", -1))
    attempt("qos None:", lambda: node.create_publisher(String, "a", None))
    attempt("QoSProfile(depth=-1):", lambda: QoSProfile(depth=-1))
    attempt("QoSProfile():", lambda: QoSProfile())
    attempt("instance for a class:", lambda: node.create_publisher(String(), "a", 10))
    attempt("str for a class:", lambda: node.create_publisher("std_msgs/msg/String", "a", 10))
    attempt("int as a class:", lambda: node.create_publisher(int, "a", 10))
    attempt("service class for a topic:", lambda: node.create_publisher(Trigger, "a", 10))
    attempt("message class for a service:", lambda: node.create_service(String, "s", lambda q, r: r))
    attempt("message class for a client:", lambda: node.create_client(String, "s"))
    attempt("topic None:", lambda: node.create_publisher(String, None, 10))
    publisher = node.create_publisher(String, "b", 7)
    subscription = node.create_subscription(String, "b", print, 3)
    for entity in (publisher, subscription):
        qos = entity.qos_profile
        print(type(entity).__name__, qos.depth, qos.history, qos.reliability, qos.durability)
    print("publishers:", sorted(p.topic_name for p in node.publishers))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
