"""QoS event callbacks, as the QoS demos set them: a publisher's and a subscription's
incompatible_qos callbacks (given, they replace rclpy's warning) receive the event's counts
and the policy that did not match (rmw's kind, equal to rclpy.qos.QoSPolicyKind's), a count
that grows with a second incompatible endpoint, use_default_callbacks=False silencing the
warning, an endpoint with no callbacks still warning, and the deprecated rclpy.qos_event."""
import time
import warnings

import rclpy
from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
from rclpy.node import Node
from rclpy.qos import (
    DurabilityPolicy,
    QoSPolicyKind,
    QoSProfile,
    ReliabilityPolicy,
    qos_policy_name_from_kind,
)
from std_msgs.msg import String


def settle(node, rounds=10):
    time.sleep(0.5)  # discovery done: the executor then sees every QoS event at once
    for _ in range(rounds):
        rclpy.spin_once(node, timeout_sec=0.05)


def main():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        from rclpy.qos_event import SubscriptionEventCallbacks as Deprecated
    print("qos_event:", Deprecated is SubscriptionEventCallbacks, [(w.category.__name__, str(w.message)) for w in caught])
    rclpy.init()
    node = Node("qos_events")
    events = []

    def recorder(label):
        def record(event):
            kind = event.last_policy_kind
            events.append((label, event.total_count, event.total_count_change, kind.name, int(kind),
                           kind == QoSPolicyKind.RELIABILITY, qos_policy_name_from_kind(kind)))
        return record

    best_effort = QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)
    callbacks = PublisherEventCallbacks(incompatible_qos=recorder("pub"))
    print("callbacks:", sorted(vars(callbacks)), callbacks.use_default_callbacks)
    node.create_publisher(String, "chatter", best_effort, event_callbacks=callbacks)
    node.create_subscription(String, "chatter", lambda m: None, 10,
                             event_callbacks=SubscriptionEventCallbacks(incompatible_qos=recorder("sub")))
    settle(node)
    for event in sorted(events):
        print(*event)
    events.clear()
    print("a second reliable subscription, no callbacks of its own:")
    node.create_subscription(String, "chatter", lambda m: None, 10)
    settle(node)
    for event in sorted(events):
        print(*event)
    print("use_default_callbacks=False, then a transient-local subscription with a callback:")
    node.create_publisher(String, "status", 10, event_callbacks=PublisherEventCallbacks(use_default_callbacks=False))
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    events.clear()
    node.create_subscription(String, "status", lambda m: None, latched,
                             event_callbacks=SubscriptionEventCallbacks(incompatible_qos=recorder("latched")))
    settle(node)
    for event in sorted(events):
        print(*event)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
