"""Service introspection: the service_msgs events a service and its clients publish
on ``<service>/_service_event`` once ``configure_introspection`` turns it on.

As rcl's: a client publishes REQUEST_SENT and RESPONSE_RECEIVED, a service
REQUEST_RECEIVED and RESPONSE_SENT, each stamped by the clock given, with the
client's GID and the request's sequence number (a client counts its requests
from 1, introspected or not); with CONTENTS the request or response rides
along, with METADATA neither, with OFF nothing is published.
"""

from __future__ import annotations

import hashlib
from enum import IntEnum
from typing import Any

from turtletui.interfaces.service_msgs import ServiceEventInfo


class ServiceIntrospectionState(IntEnum):
    """How much of each call introspection publishes."""

    OFF = 0
    METADATA = 1
    CONTENTS = 2

    def __str__(self) -> str:
        return f"{type(self).__name__}.{self.name}"  # pybind11's enums print so, not as ints


ServiceIntrospectionState.__module__ = "rclpy._rclpy_pybind11.service_introspection"

_SENT_BY_CLIENT: dict[int, tuple[list[int], int]] = {}
"""(client GID, sequence number) of each request in flight in this process, by
id(request): what the service's events name (rcl reads them from the middleware)."""


class Introspection:
    """The introspection of one service or client: its state and event publisher."""

    def __init__(self, node: Any, srv_type: Any, service_name: str) -> None:
        self._node = node
        self._srv_type = srv_type
        self._topic = f"{service_name}/_service_event"
        self._state = ServiceIntrospectionState.OFF
        self._clock: Any = None
        self._publisher: Any = None

    def configure(self, clock: Any, qos_profile: Any, state: ServiceIntrospectionState) -> None:
        if self._publisher is not None:
            self._publisher.destroy()
            self._publisher = None
        self._state = ServiceIntrospectionState(state)
        self._clock = clock
        if self._state is not ServiceIntrospectionState.OFF:
            node = self._node
            self._publisher = node.create_publisher(self._srv_type.Event, self._topic, qos_profile)
            node._entities.remove(self._publisher)  # rcl's own, not among the node's publishers

    def publish(self, event_type: int, gid: list[int], sequence: int, request: Any = None, response: Any = None) -> None:
        """Publish one event (nothing while introspection is off)."""
        if self._publisher is None:
            return
        contents = self._state is ServiceIntrospectionState.CONTENTS
        info = ServiceEventInfo(
            event_type=event_type, stamp=self._clock.now().to_msg(), client_gid=gid, sequence_number=sequence
        )
        self._publisher.publish(
            self._srv_type.Event(
                info=info,
                request=[request] if contents and request is not None else [],
                response=[response] if contents and response is not None else [],
            )
        )

    def destroy(self) -> None:
        if self._publisher is not None:
            self._publisher.destroy()
            self._publisher = None


def client_gid(node_name: str, service_name: str, number: int) -> list[int]:
    """A client's 16-byte GID: made up, the same in every run."""
    return list(hashlib.md5(f"{node_name} {service_name} {number}".encode()).digest())  # noqa: S324 - a name


def request_sent(request: Any, gid: list[int], sequence: int) -> None:
    _SENT_BY_CLIENT[id(request)] = (gid, sequence)


def request_received(request: Any) -> tuple[list[int], int]:
    """The GID of the client that sent ``request`` and its sequence number (zeros
    if unknown: a client in another process)."""
    return _SENT_BY_CLIENT.pop(id(request), ([0] * 16, 0))


def request_answered(request: Any) -> None:
    """Forget ``request`` (its service was in another process, which never asked)."""
    _SENT_BY_CLIENT.pop(id(request), None)
