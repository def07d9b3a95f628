"""Messages for a node nobody spins wait in its subscriptions' queues, keep-last: ten messages
published while only the publishing node spins leave the newest one for a subscription of
depth 1 and the newest five for one of depth 5, delivered once the node is spun; a timer of
a node spun only after a second runs once at once, not once per missed period."""
import time

import rclpy
from rclpy.node import Node
from std_msgs.msg import Int32


def main():
    rclpy.init()
    talker = Node("keep_talker")
    listener = Node("keep_listener")
    heard = {1: [], 5: []}
    listener.create_subscription(Int32, "kept", lambda msg: heard[1].append(msg.data), 1)
    listener.create_subscription(Int32, "kept", lambda msg: heard[5].append(msg.data), 5)
    publisher = talker.create_publisher(Int32, "kept", 10)
    for _ in range(200):
        if publisher.get_subscription_count() >= 2:
            break
        rclpy.spin_once(talker, timeout_sec=0.05)
    print("listeners:", publisher.get_subscription_count())
    for n in range(10):
        publisher.publish(Int32(data=n))
        rclpy.spin_once(talker, timeout_sec=0.02)
    for _ in range(10):
        rclpy.spin_once(talker, timeout_sec=0.05)
    print("before spinning the listener:", heard)
    for _ in range(12):
        rclpy.spin_once(listener, timeout_sec=0.1)
    print("depth 1 kept:", heard[1])
    print("depth 5 kept:", heard[5])

    ticks = []
    listener.create_timer(0.1, lambda: ticks.append(1))
    time.sleep(1.05)
    for _ in range(5):
        rclpy.spin_once(listener, timeout_sec=0)
    print("timer after a second unspun: ran", len(ticks), "time(s) at once")
    for _ in range(100):
        if len(ticks) >= 3:
            break
        rclpy.spin_once(listener, timeout_sec=0.5)
    print("and goes on:", len(ticks) >= 3)
    talker.destroy_node()
    listener.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
