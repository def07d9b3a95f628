"""``rclpy.wait_for_message.wait_for_message``: the next message of a topic, without spinning."""

from __future__ import annotations

from typing import Any

from turtletui.compat.qos import QoSProfile

_NS = 1_000_000_000


def wait_for_message(
    msg_type: Any,
    node: Any,
    topic: str,
    *,
    qos_profile: QoSProfile | int = 1,
    time_to_wait: int | float = -1,
) -> tuple[bool, Any]:
    """Wait for the next message on ``topic``: ``(True, msg)``, or ``(False, None)``
    after ``time_to_wait`` seconds (negative: for ever) or at the end of the run.

    As rclpy's, it waits on a subscription of its own: none of the node's
    callbacks run meanwhile, and the subscription is destroyed afterwards."""
    subscription = node.create_subscription(msg_type, topic, lambda _msg: None, qos_profile)
    queue = subscription._record.queue
    timeout_ns = None if time_to_wait < 0 else int(min(time_to_wait, 1e9) * _NS)
    try:
        if queue or node.context.host.spin_until(lambda: bool(queue), timeout_ns, callbacks=False):
            return True, queue.popleft()
    finally:
        node.destroy_subscription(subscription)
    return False, None
