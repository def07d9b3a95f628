"""tf2_ros's TransformBroadcaster (/tf) and StaticTransformBroadcaster (/tf_static)."""

from __future__ import annotations

from typing import Any

from turtletui.compat.qos import DurabilityPolicy, HistoryPolicy, QoSProfile
from turtletui.interfaces.tf2_msgs import TFMessage


def _as_list(transform: Any) -> list:
    if isinstance(transform, list):
        return transform
    return list(transform) if hasattr(transform, "__iter__") else [transform]


class TransformBroadcaster:
    """Publishes TransformStamped messages on /tf (depth 100 by default)."""

    def __init__(self, node: Any, qos: QoSProfile | int | None = None) -> None:
        self.pub_tf = node.create_publisher(TFMessage, "/tf", QoSProfile(depth=100) if qos is None else qos)

    def sendTransform(self, transform: Any) -> None:  # noqa: N802 - tf2_ros's name
        """Send a transform, or a list of them."""
        self.pub_tf.publish(TFMessage(transforms=_as_list(transform)))


class StaticTransformBroadcaster:
    """Publishes transforms that never change on /tf_static (transient local,
    depth 1): each send republishes every child frame sent so far, the first
    transform given for each."""

    def __init__(self, node: Any, qos: QoSProfile | int | None = None) -> None:
        if qos is None:
            qos = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, history=HistoryPolicy.KEEP_LAST)
        self.pub_tf = node.create_publisher(TFMessage, "/tf_static", qos)
        self.net_message = TFMessage()
        self._child_frame_ids: set[str] = set()

    def sendTransform(self, transform: Any) -> None:  # noqa: N802 - tf2_ros's name
        """Send a static transform, or a list of them."""
        for t in _as_list(transform):
            if t.child_frame_id not in self._child_frame_ids:
                self._child_frame_ids.add(t.child_frame_id)
                self.net_message.transforms.append(t)
        self.pub_tf.publish(self.net_message)
