"""rclpy's MessageInfo: what a subscription callback with a second parameter
gets with each message (``def on_pose(self, msg, info)``), Iron on.

rclpy decides once, when the subscription is made, by binding the callback's
signature: one argument binds, the message only; else two bind, the message
and its MessageInfo; else RuntimeError (rclpy/subscription.py, the
``callback`` setter). Humble passes the message only, whatever the callback.
The info is a plain dict, as rclpy's ``take_message`` makes it; the
timestamps are the simulated clock's (ROS time, ns) when the message was
published and when it reached the subscription.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable
from typing import Any, TypedDict

from turtletui.compat.distro import current_distro
from turtletui.compat.graph_info import publisher_gid
from turtletui.graph import core

RMW_IMPLEMENTATION = "rmw_fastrtps_cpp"
"""The implementation a publisher GID names: Fast DDS, the default rmw."""


class MessageInfo(TypedDict):
    """``rclpy.subscription.MessageInfo`` (Kilted): the keys of the dict."""

    source_timestamp: int
    received_timestamp: int
    publication_sequence_number: int | None
    reception_sequence_number: int | None
    publisher_gid: dict | None


_NEITHER = (
    "Subscription.__init__(): callback should be either be callable with one argument"
    "(to get only the message) or two (to get message and message info)"
)


def takes_message_info(callback: Callable) -> bool:
    """Whether rclpy hands subscription callback ``callback`` each message's
    MessageInfo too: not if it can be called with the message alone, yes if
    with the message and the info; RuntimeError, in rclpy's words, if with
    neither (or it is no callable). Always False on Humble, whose executors
    pass the message only (and whose rclpy takes anything as a callback:
    turtletui refuses what is not callable at once, with a TypeError)."""
    if current_distro() == "humble":
        if not callable(callback):
            raise TypeError(f"create_subscription() needs a callable callback, got {callback!r}")
        return False
    try:
        inspect.signature(callback).bind(object())
        return False
    except TypeError:
        pass
    try:
        inspect.signature(callback).bind(object(), object())
        return True
    except TypeError:
        pass
    raise RuntimeError(_NEITHER)


def message_info_maker(graph: core.Graph) -> Callable[[core.MessageOrigin], dict[str, Any]]:
    """What turns the origin of a message queued for a subscription of
    ``graph`` into the dict rclpy passes: Fast DDS's, which counts each
    publisher's messages but not a subscription's receptions
    (reception_sequence_number is None); ``publisher_gid`` from Kilted on."""
    epoch_ns = graph.epoch_ns
    with_gid = current_distro() not in ("humble", "jazzy")
    def gid_of(publisher: core.Publisher | bytes | None) -> dict[str, Any] | None:
        if publisher is None:
            return None
        data = publisher if isinstance(publisher, bytes) else publisher_gid(graph, publisher)
        return {"implementation_identifier": RMW_IMPLEMENTATION, "data": data}

    def message_info(origin: core.MessageOrigin) -> dict[str, Any]:
        info = {
            "source_timestamp": epoch_ns + origin.source_ns,
            "received_timestamp": epoch_ns + origin.received_ns,
            "publication_sequence_number": origin.sequence,
            "reception_sequence_number": None,
        }
        if with_gid:
            info["publisher_gid"] = gid_of(origin.publisher)
        return info

    return message_info
