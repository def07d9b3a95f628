"""``rclpy.parameter_event_handler``: callbacks for parameter changes, from ``/parameter_events``.

As rclpy's: a callback for one parameter of one node gets its
``rcl_interfaces/Parameter`` when the node declares or changes it, a callback
for every event gets the ``ParameterEvent``; of each kind the callback added
last runs first, parameter callbacks before event callbacks.
"""

from __future__ import annotations

import threading
from collections import defaultdict
from collections.abc import Callable, Iterable, Iterator
from itertools import chain
from typing import Any

from turtletui.compat.identity import as_rclpy
from turtletui.compat.qos import QoSProfile, qos_profile_parameter_events
from turtletui.interfaces.rcl_interfaces import ParameterEvent


class ParameterCallbackHandle:
    """What ``add_parameter_callback`` returns: keep it to remove the callback."""

    def __init__(self, parameter_name: str, node_name: str, callback: Callable[[Any], None]) -> None:
        self.parameter_name = parameter_name
        self.node_name = node_name
        self.callback = callback
        self.mutex = threading.Lock()


class ParameterEventCallbackHandle:
    """What ``add_parameter_event_callback`` returns: keep it to remove the callback."""

    def __init__(self, callback: Callable[[Any], None]) -> None:
        self.callback = callback
        self.mutex = threading.Lock()


class ParameterEventHandler:
    """Subscribes ``node`` to ``/parameter_events`` and calls the callbacks added."""

    def __init__(
        self,
        node: Any,
        qos_profile: QoSProfile | int = qos_profile_parameter_events,
        callback_group: Any = None,
        event_callbacks: Any = None,
        qos_overriding_options: Any = None,
        raw: bool = False,
    ) -> None:
        self.node = node
        self.qos_profile = qos_profile
        self._parameter_callbacks: dict[tuple[str, str], list[ParameterCallbackHandle]] = defaultdict(list)
        self._event_callbacks: list[ParameterEventCallbackHandle] = []
        self._mutex = threading.Lock()
        self.parameter_event_subscription = node.create_subscription(
            ParameterEvent,
            "/parameter_events",
            self._on_event,
            qos_profile,
            callback_group=callback_group,
            event_callbacks=event_callbacks,
            qos_overriding_options=qos_overriding_options,
            raw=raw,
        )

    def destroy(self) -> None:
        self.node.destroy_subscription(self.parameter_event_subscription)

    def _on_event(self, event: Any) -> None:
        with self._mutex:
            for (parameter_name, node_name), handles in self._parameter_callbacks.items():
                parameter = self.get_parameter_from_event(event, parameter_name=parameter_name, node_name=node_name)
                if parameter:
                    for handle in handles:
                        with handle.mutex:
                            handle.callback(parameter)
            for event_handle in self._event_callbacks:
                with event_handle.mutex:
                    event_handle.callback(event)

    @staticmethod
    def get_parameter_from_event(event: Any, parameter_name: str, node_name: str) -> Any | None:
        """The new or changed parameter ``parameter_name`` of node ``node_name`` (its full name) in ``event``."""
        if event.node == node_name:
            for parameter in chain(event.new_parameters, event.changed_parameters):
                if parameter.name == parameter_name:
                    return parameter
        return None

    @staticmethod
    def get_parameters_from_event(event: Any) -> Iterable[Any]:
        """Every new and changed parameter of ``event`` (a generator, as rclpy's)."""
        return _new_and_changed(event)

    def add_parameter_callback(
        self, parameter_name: str, node_name: str, callback: Callable[[Any], None]
    ) -> ParameterCallbackHandle:
        """Call ``callback(parameter)`` when node ``node_name`` (relative to this node's
        namespace, or absolute; empty: this node) declares or changes ``parameter_name``."""
        handle = ParameterCallbackHandle(parameter_name, self._resolve_path(node_name), callback)
        with self._mutex:
            self._parameter_callbacks[(parameter_name, handle.node_name)].insert(0, handle)
        return handle

    def remove_parameter_callback(self, handle: ParameterCallbackHandle) -> None:
        with self._mutex:
            key = (handle.parameter_name, handle.node_name)
            handles = self._parameter_callbacks.get(key, [])
            if handle not in handles:
                raise RuntimeError("Callback doesn't exist")
            handles.remove(handle)
            if not handles:
                del self._parameter_callbacks[key]

    def add_parameter_event_callback(self, callback: Callable[[Any], None]) -> ParameterEventCallbackHandle:
        """Call ``callback(event)`` for every ParameterEvent of any node."""
        handle = ParameterEventCallbackHandle(callback)
        with self._mutex:
            self._event_callbacks.insert(0, handle)
        return handle

    def remove_parameter_event_callback(self, handle: ParameterEventCallbackHandle) -> None:
        with self._mutex:
            if handle not in self._event_callbacks:
                raise RuntimeError("Callback doesn't exist")
            self._event_callbacks.remove(handle)

    def _resolve_path(self, node_path: str | None = None) -> str:
        if not node_path:
            return self.node.get_fully_qualified_name()
        if node_path.startswith("/"):
            return node_path
        resolved = "/".join([self.node.get_namespace().lstrip("/"), node_path])
        return resolved if resolved.startswith("/") else f"/{resolved}"


def _new_and_changed(event: Any) -> Iterator[Any]:
    yield from chain(event.new_parameters, event.changed_parameters)


as_rclpy(
    "rclpy.parameter_event_handler", ParameterEventHandler, ParameterCallbackHandle, ParameterEventCallbackHandle
)
