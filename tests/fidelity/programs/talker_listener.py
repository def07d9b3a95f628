"""A talker and a listener in one node (the official pub/sub tutorial, in one file)."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class TalkerListener(Node):
    def __init__(self):
        super().__init__("talker_listener")
        self.publisher = self.create_publisher(String, "chatter", 10)
        self.subscription = self.create_subscription(String, "chatter", self.on_message, 10)
        self.count = 0
        self.heard = 0
        self.timer = self.create_timer(0.1, self.on_timer)

    def on_timer(self):
        if self.publisher.get_subscription_count() == 0:
            return  # wait until the listener is matched, as a robust talker does
        if self.heard < self.count:
            return  # the last one is still on its way (a loaded machine): the log keeps one order
        msg = String()
        msg.data = f"Hello World: {self.count}"
        self.publisher.publish(msg)
        self.get_logger().info(f'Publishing: "{msg.data}"')
        self.count += 1

    def on_message(self, msg):
        self.get_logger().info(f'I heard: "{msg.data}"')
        self.heard += 1


def main():
    rclpy.init()
    node = TalkerListener()
    while rclpy.ok() and node.heard < 5:
        rclpy.spin_once(node, timeout_sec=1.0)
    print(f"heard {node.heard} messages")
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
