"""Subscription callbacks that take a second parameter get each message's MessageInfo (a dict:
timestamps, the publisher's sequence number and GID); one that can take the message alone gets
only it; one that can take neither (or is no callable) is refused. Only what is the same every
run is printed."""
import functools

import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from rclpy.subscription import MessageInfo
from std_msgs.msg import String


class Listener:
    def __init__(self):
        self.infos = []

    def on_message(self, msg, info):
        self.infos.append((msg.data, info))


def main():
    rclpy.init()
    node = Node("info_listener")
    first = node.create_publisher(String, "chatter", 10)
    second = node.create_publisher(String, "chatter", 10)
    listener = Listener()
    calls = {"default": [], "star": [], "partial": [], "extra": []}
    node.create_subscription(String, "chatter", listener.on_message, 10)
    node.create_subscription(String, "chatter", lambda msg, info=None: calls["default"].append(info), 10)
    node.create_subscription(String, "chatter", lambda *args: calls["star"].append(len(args)), 10)
    node.create_subscription(
        String, "chatter", functools.partial(lambda tag, msg, info: calls["partial"].append(type(info).__name__), "p"), 10
    )
    node.create_subscription(
        String, "chatter", lambda msg, info, extra=None: calls["extra"].append(info["publication_sequence_number"]), 10
    )
    for bad in (lambda: None, lambda a, b, c: None, lambda *, msg: None, None):
        try:
            node.create_subscription(String, "chatter", bad, 10)
            print("accepted a callback it cannot call")
        except RuntimeError as err:
            print("RuntimeError:", err)
    while first.get_subscription_count() < 5 or second.get_subscription_count() < 5:
        rclpy.spin_once(node, timeout_sec=0.1)
    for i in range(3):
        first.publish(String(data=f"first {i}"))
        second.publish(String(data=f"second {i}"))
    while len(listener.infos) < 6 or len(calls["extra"]) < 6:
        rclpy.spin_once(node, timeout_sec=0.1)
    now = node.get_clock().now().nanoseconds

    gids = {bytes(info.endpoint_gid) for info in node.get_publishers_info_by_topic("chatter")}
    by_publisher = {}
    for data, info in listener.infos:
        by_publisher.setdefault(data.split()[0], []).append(info)
    data, info = listener.infos[0]
    print("info:", type(info).__name__, list(info))
    print("gid keys:", list(info["publisher_gid"]), info["publisher_gid"]["implementation_identifier"])
    for name, infos in sorted(by_publisher.items()):
        print(name, "sequence numbers:", [i["publication_sequence_number"] for i in infos])
        print(name, "reception sequence numbers:", [i["reception_sequence_number"] for i in infos])
        print(name, "one GID:", len({i["publisher_gid"]["data"] for i in infos}) == 1)
        print(name, "GID listed for the topic:", infos[0]["publisher_gid"]["data"] in gids)
        print(name, "GID bytes:", type(infos[0]["publisher_gid"]["data"]).__name__, len(infos[0]["publisher_gid"]["data"]))
    firsts = {infos[0]["publisher_gid"]["data"] for infos in by_publisher.values()}
    print("publishers' GIDs differ:", len(firsts) == 2)
    stamps = [(i["source_timestamp"], i["received_timestamp"]) for _, i in listener.infos]
    print("received at or after sent:", all(received >= source for source, received in stamps))
    print("sent within the last 10 s of ROS time:", all(0 <= now - source < 10**10 for source, _ in stamps))
    print("timestamps are int:", {type(t).__name__ for pair in stamps for t in pair})
    print("defaulted info:", calls["default"])
    print("star args:", calls["star"])
    print("partial:", calls["partial"])
    print("extra parameter with a default:", sorted(calls["extra"]))
    print("MessageInfo keys:", list(MessageInfo.__annotations__))

    latched = QoSProfile(depth=5, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    keeper = node.create_publisher(String, "map", latched)
    for i in range(3):
        keeper.publish(String(data=f"map v{i}"))
    late = []
    node.create_subscription(String, "map", lambda msg, info: late.append((msg.data, info)), latched)
    while len(late) < 3:
        rclpy.spin_once(node, timeout_sec=0.1)
    print("late joiner:", [(data, info["publication_sequence_number"]) for data, info in late])
    print("late joiner received at or after sent:", all(i["received_timestamp"] >= i["source_timestamp"] for _, i in late))
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
