"""Invalid node names, namespaces, topic and service names: rclpy's exception classes and texts."""
import rclpy
from rclpy.exceptions import (
    InvalidNamespaceException,
    InvalidNodeNameException,
    InvalidServiceNameException,
    InvalidTopicNameException,
    NameValidationException,
)
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Empty


def attempt(label, make):
    try:
        make()
        print(label, "-> ok")
    except NameValidationException as err:
        print(label, "->", type(err).__name__)
        print(err)


def main():
    rclpy.init()
    for name in ["", "1abc", "my-node", "ab$", "_private", "x1"]:
        attempt(f"node {name!r}", lambda name=name: Node(name).destroy_node())
    for ns in ["1x", "a/", "/a//b", "/a b", "ns", "/x/2y", ""]:
        attempt(f"namespace {ns!r}", lambda ns=ns: Node("n", namespace=ns).destroy_node())
    node = Node("names")
    for topic in ["a b", "1abc", "foo//bar", "a~", "x/", "a/1b", "", "é", "~/x", "a{b", "/"]:
        attempt(f"topic {topic!r}", lambda topic=topic: node.create_publisher(String, topic, 10))
    for service in ["a b", "1x", "x//y", "ok_service"]:
        attempt(f"service {service!r}", lambda service=service: node.create_service(Empty, service, lambda q, r: r))
        attempt(f"client {service!r}", lambda service=service: node.create_client(Empty, service))
    print(issubclass(InvalidTopicNameException, NameValidationException),
          issubclass(InvalidServiceNameException, NameValidationException),
          issubclass(InvalidNodeNameException, NameValidationException),
          issubclass(InvalidNamespaceException, NameValidationException))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
