"""Messages as bytes on a topic: a subscription made with raw=True gets each message's CDR
bytes (what rclpy.serialization.serialize_message gives) and deserializes them itself, and a
publisher publishes bytes that were serialized before, which an ordinary subscription
receives as the message."""
import rclpy
from geometry_msgs.msg import Twist, Vector3
from rclpy.node import Node
from rclpy.serialization import deserialize_message, serialize_message
from std_msgs.msg import String


class Recorder(Node):
    def __init__(self):
        super().__init__("recorder")
        self.raw = []
        self.decoded = []
        self.create_subscription(Twist, "cmd_vel", self.raw.append, 10, raw=True)
        self.create_subscription(Twist, "cmd_vel", self.decoded.append, 10)
        self.strings = []
        self.create_subscription(String, "chatter", self.strings.append, 10, raw=True)
        self.twist_pub = self.create_publisher(Twist, "cmd_vel", 10)
        self.string_pub = self.create_publisher(String, "chatter", 10)


def spin_a_while(node):
    for _ in range(10):
        rclpy.spin_once(node, timeout_sec=0.05)


def main():
    rclpy.init()
    node = Recorder()
    twist = Twist(linear=Vector3(x=1.5), angular=Vector3(z=-0.5))
    node.twist_pub.publish(twist)
    node.twist_pub.publish(serialize_message(Twist(linear=Vector3(x=2.0))))
    node.string_pub.publish(String(data="hello"))
    node.string_pub.publish(serialize_message(String(data="from bytes")))
    spin_a_while(node)
    for data in node.raw:
        print(f"raw: {type(data).__name__} of {len(data)} bytes, {data.hex()}")
        print(f"  {deserialize_message(data, Twist)}")
    print("raw equals serialize_message:", node.raw[0] == serialize_message(twist))
    for message in node.decoded:
        print(f"decoded: {message}")
    for data in node.strings:
        print(f"string raw: {data!r} -> {deserialize_message(data, String).data!r}")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
