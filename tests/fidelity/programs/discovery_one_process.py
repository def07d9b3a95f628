"""Discovery inside one process: two nodes of one program share a DDS
participant, so a publisher matches the subscription at once and even the
first message, published right after create_publisher, arrives (between
processes it would be lost until discovery completes)."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import String


def main():
    rclpy.init()
    listener = Node("listener")
    talker = Node("talker")
    heard = []
    sub = listener.create_subscription(String, "chatter", lambda msg: heard.append(msg.data), 10)
    pub = talker.create_publisher(String, "chatter", 10)
    print(f"subscriptions matched at once: {pub.get_subscription_count()}")
    print(f"publishers matched at once: {sub.get_publisher_count()}")
    pub.publish(String(data="first"))
    pub.publish(String(data="second"))
    executor = SingleThreadedExecutor()
    executor.add_node(listener)
    executor.add_node(talker)
    for _ in range(20):
        executor.spin_once(timeout_sec=0.05)
        if len(heard) == 2:
            break
    print("heard:", ", ".join(heard))
    executor.shutdown()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
