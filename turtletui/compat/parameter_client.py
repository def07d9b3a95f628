"""``rclpy.parameter_client.AsyncParameterClient``: another node's parameters,
through its parameter services (turtletui.compat.parameter_service).

Each request returns a Future of the rcl_interfaces response; the reply
arrives while the client's node spins, as in rclpy 9.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from typing import Any

from turtletui.compat.parameter import Parameter, parameter_dict_from_yaml_file
from turtletui.compat.qos import (
    QoSProfile,
    qos_profile_parameter_events,
    qos_profile_services_default,
)
from turtletui.compat.task import Future
from turtletui.interfaces.rcl_interfaces import (
    DescribeParameters,
    GetParameters,
    GetParameterTypes,
    ListParameters,
    ParameterEvent,
    SetParameters,
    SetParametersAtomically,
)

_POLL_S = 0.25
"""How often wait_for_services looks again, as rclpy's (simulated seconds)."""


class AsyncParameterClient:
    """Lists, gets, sets and describes the parameters of the node ``remote_node_name``."""

    def __init__(
        self,
        node: Any,
        remote_node_name: str,
        qos_profile: QoSProfile = qos_profile_services_default,
        callback_group: Any = None,
    ) -> None:
        self.remote_node_name = remote_node_name
        self.node = node

        def client(srv_type: Any, service: str) -> Any:
            return node.create_client(
                srv_type, f"{remote_node_name}/{service}", qos_profile=qos_profile, callback_group=callback_group
            )

        self._get_parameter_client = client(GetParameters, "get_parameters")
        self._list_parameter_client = client(ListParameters, "list_parameters")
        self._set_parameter_client = client(SetParameters, "set_parameters")
        self._get_parameter_types_client = client(GetParameterTypes, "get_parameter_types")
        self._describe_parameters_client = client(DescribeParameters, "describe_parameters")
        self._set_parameters_atomically_client = client(SetParametersAtomically, "set_parameters_atomically")

    def services_are_ready(self) -> bool:
        """Whether the remote node serves all six parameter services."""
        return all(
            client.service_is_ready()
            for client in (
                self._list_parameter_client,
                self._set_parameter_client,
                self._get_parameter_client,
                self._get_parameter_types_client,
                self._describe_parameters_client,
                self._set_parameters_atomically_client,
            )
        )

    def wait_for_services(self, timeout_sec: float | None = None) -> bool:
        """Wait (looking every 0.25 s, as rclpy does) for the services; False on timeout."""
        remaining = float("inf") if timeout_sec is None else timeout_sec
        while not self.services_are_ready() and remaining > 0.0:
            time.sleep(_POLL_S)
            remaining -= _POLL_S
        return self.services_are_ready()

    @staticmethod
    def _send(client: Any, request: Any, callback: Callable[[Future], None] | None) -> Future:
        future = client.call_async(request)
        if callback:
            future.add_done_callback(callback)
        return future

    def list_parameters(
        self,
        prefixes: list[str] | None = None,
        depth: int | None = None,
        callback: Callable[[Future], None] | None = None,
    ) -> Future:
        """A Future of ListParameters.Response: the names under ``prefixes``, ``depth`` levels deep."""
        request = ListParameters.Request()
        if prefixes:
            request.prefixes = prefixes
        if depth:
            request.depth = depth
        return self._send(self._list_parameter_client, request, callback)

    def get_parameters(self, names: list[str], callback: Callable[[Future], None] | None = None) -> Future:
        """A Future of GetParameters.Response: one ParameterValue per name (none if one is unknown)."""
        return self._send(self._get_parameter_client, GetParameters.Request(names=names), callback)

    def set_parameters(
        self, parameters: Sequence[Any], callback: Callable[[Future], None] | None = None
    ) -> Future:
        """A Future of SetParameters.Response: one result per parameter, each set on its own."""
        request = SetParameters.Request(parameters=_messages(parameters))
        return self._send(self._set_parameter_client, request, callback)

    def describe_parameters(self, names: list[str], callback: Callable[[Future], None] | None = None) -> Future:
        """A Future of DescribeParameters.Response: one ParameterDescriptor per name."""
        return self._send(self._describe_parameters_client, DescribeParameters.Request(names=names), callback)

    def get_parameter_types(self, names: list[str], callback: Callable[[Future], None] | None = None) -> Future:
        """A Future of GetParameterTypes.Response: one ParameterType number per name."""
        return self._send(self._get_parameter_types_client, GetParameterTypes.Request(names=names), callback)

    def set_parameters_atomically(
        self, parameters: Sequence[Any], callback: Callable[[Future], None] | None = None
    ) -> Future:
        """A Future of SetParametersAtomically.Response: all set, or none."""
        request = SetParametersAtomically.Request(parameters=_messages(parameters))
        return self._send(self._set_parameters_atomically_client, request, callback)

    def delete_parameters(self, names: list[str], callback: Callable[[Future], None] | None = None) -> Future:
        """Unset parameters (only dynamically typed ones can be): a Future of SetParameters.Response."""
        request = SetParameters.Request(parameters=[Parameter(name=name).to_parameter_msg() for name in names])
        return self._send(self._set_parameter_client, request, callback)

    def load_parameter_file(
        self, parameter_file: str, use_wildcard: bool = False, callback: Callable[[Future], None] | None = None
    ) -> Future:
        """Set what a YAML parameter file gives the remote node: a Future of SetParameters.Response."""
        param_dict = parameter_dict_from_yaml_file(parameter_file, use_wildcard, target_nodes=[self.remote_node_name])
        return self.set_parameters(list(param_dict.values()), callback=callback)

    def load_parameter_file_atomically(
        self, parameter_file: str, use_wildcard: bool = False, callback: Callable[[Future], None] | None = None
    ) -> Future:
        """As load_parameter_file, all or none: a Future of SetParametersAtomically.Response."""
        param_dict = parameter_dict_from_yaml_file(parameter_file, use_wildcard, target_nodes=[self.remote_node_name])
        return self.set_parameters_atomically(list(param_dict.values()), callback=callback)

    def on_parameter_event(
        self,
        callback: Callable[..., None],
        qos_profile: QoSProfile = qos_profile_parameter_events,
        *,
        callback_group: Any = None,
        event_callbacks: Any = None,
        qos_overriding_options: Any = None,
        raw: bool = False,
    ) -> Any:
        """Subscribe ``callback`` to /parameter_events."""
        return self.node.create_subscription(
            ParameterEvent,
            "/parameter_events",
            callback,
            qos_profile,
            callback_group=callback_group,
            event_callbacks=event_callbacks,
            qos_overriding_options=qos_overriding_options,
            raw=raw,
        )


def _messages(parameters: Sequence[Any]) -> list[Any]:
    return [p.to_parameter_msg() if isinstance(p, Parameter) else p for p in parameters]
