"""tf2_ros's TransformListener: fills a Buffer from /tf and /tf_static."""

from __future__ import annotations

import threading
from typing import Any

from turtletui.compat.callback_groups import ReentrantCallbackGroup
from turtletui.compat.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from turtletui.interfaces.tf2_msgs import TFMessage

DEFAULT_TF_TOPIC = "/tf"
DEFAULT_STATIC_TF_TOPIC = "/tf_static"
AUTHORITY = "default_authority"


class TransformListener:
    """Subscribes ``node`` to /tf (depth 100, volatile) and /tf_static (depth
    100, transient local) in a reentrant group, and stores what arrives in
    ``buffer``. ``spin_thread=True`` spins ``node`` on a thread of its own."""

    def __init__(
        self,
        buffer: Any,
        node: Any,
        *,
        spin_thread: bool = False,
        qos: QoSProfile | int | None = None,
        static_qos: QoSProfile | int | None = None,
        tf_topic: str = DEFAULT_TF_TOPIC,
        tf_static_topic: str = DEFAULT_STATIC_TF_TOPIC,
    ) -> None:
        if qos is None:
            qos = QoSProfile(depth=100, durability=DurabilityPolicy.VOLATILE, history=HistoryPolicy.KEEP_LAST)
        if static_qos is None:
            static_qos = QoSProfile(
                depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL, history=HistoryPolicy.KEEP_LAST
            )
        self.buffer = buffer
        self.node = node
        if getattr(buffer, "_node", False) is None:
            buffer._node = node  # the node whose executor a blocking lookup can count on
        self.group = ReentrantCallbackGroup()
        self.tf_sub = node.create_subscription(TFMessage, tf_topic, self.callback, qos, callback_group=self.group)
        self.tf_static_sub = node.create_subscription(
            TFMessage, tf_static_topic, self.static_callback, static_qos, callback_group=self.group
        )
        if spin_thread:
            if getattr(node.context.host, "scheduler", None) is None:  # the in-process host: one thread
                raise RuntimeError(
                    "TransformListener(spin_thread=True) spins its node on a thread of its own, and a controller"
                    " run in-process can spin on its main thread only; run it sandboxed (without --in-process)"
                )
            from turtletui.compat.executors import SingleThreadedExecutor

            self.executor = SingleThreadedExecutor()

            def run() -> None:
                self.executor.add_node(self.node)
                self.executor.spin()
                self.executor.remove_node(self.node)

            self.dedicated_listener_thread = threading.Thread(target=run, daemon=True)
            self.dedicated_listener_thread.start()

    def unregister(self) -> None:
        """Destroy both subscriptions."""
        self.node.destroy_subscription(self.tf_sub)
        self.node.destroy_subscription(self.tf_static_sub)

    def callback(self, data: TFMessage) -> None:
        for transform in data.transforms:
            self.buffer.set_transform(transform, AUTHORITY)

    def static_callback(self, data: TFMessage) -> None:
        for transform in data.transforms:
            self.buffer.set_transform_static(transform, AUTHORITY)
