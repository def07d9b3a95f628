"""rclpy.wait_for_message: the next message of a topic while nothing spins (a timer's callback
does not run meanwhile), a timeout on a silent topic, and the subscription it leaves behind (none)."""
import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from rclpy.wait_for_message import wait_for_message
from std_msgs.msg import String


def main():
    rclpy.init()
    talker = Node("talker")
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    publisher = talker.create_publisher(String, "greeting", latched)
    publisher.publish(String(data="hello"))
    ticks = []
    talker.create_timer(0.1, lambda: ticks.append(1))
    listener = Node("listener")
    ok, msg = wait_for_message(String, listener, "greeting", qos_profile=latched, time_to_wait=5.0)
    print(f"got: {ok} {msg.data if ok else None}")
    ok, msg = wait_for_message(String, listener, "silence", time_to_wait=0.5)
    print(f"silent topic: {ok} {msg}")
    print(f"timer ran while waiting: {bool(ticks)}")
    print(f"subscriptions left: {listener.count_subscribers('greeting')} on greeting")
    talker.destroy_node()
    listener.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
