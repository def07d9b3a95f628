"""Node names, namespaces and fully qualified names, and how topic names resolve."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


def main():
    rclpy.init()
    plain = Node("plain")
    spaced = Node("spaced", namespace="robot1")
    nested = Node("nested", namespace="/fleet/robot2")
    for node in (plain, spaced, nested):
        print(node.get_name(), node.get_namespace(), node.get_fully_qualified_name())
        node.get_logger().info(f"logger name {node.get_logger().name}")
        for topic in ("chatter", "/absolute", "~/private", "a/b"):
            print(" ", topic, "->", node.resolve_topic_name(topic))
    pub = spaced.create_publisher(String, "chatter", 10)
    print("publisher topic:", pub.topic_name)
    for node in (plain, spaced, nested):
        node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
