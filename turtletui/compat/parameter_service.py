"""``rclpy.parameter_service.ParameterService``: the services through which other
nodes (and ``ros2 param``) read and set a node's parameters.

As rclpy 9's, each is a service of the node, ``<node name>/<service>``, whose
callbacks run in the node's default callback group when the node spins.
"""

from __future__ import annotations

import weakref
from typing import Any

from turtletui.compat.exceptions import (
    ParameterNotDeclaredException,
    ParameterUninitializedException,
)
from turtletui.compat.parameter import Parameter
from turtletui.interfaces.rcl_interfaces import (
    DescribeParameters,
    GetParameters,
    GetParameterTypes,
    ListParameters,
    ListParametersResult,
    SetParameters,
    SetParametersAtomically,
    SetParametersResult,
)


class ParameterService:
    """Serves ``node``'s parameters to the graph."""

    def __init__(self, node: Any) -> None:
        self._node_weak_ref = weakref.ref(node)
        name = node.get_name()
        for srv_type, short, callback in (
            (DescribeParameters, "describe_parameters", self._describe_parameters_callback),
            (GetParameters, "get_parameters", self._get_parameters_callback),
            (GetParameterTypes, "get_parameter_types", self._get_parameter_types_callback),
            (ListParameters, "list_parameters", self._list_parameters_callback),
            (SetParameters, "set_parameters", self._set_parameters_callback),
            (SetParametersAtomically, "set_parameters_atomically", self._set_parameters_atomically_callback),
        ):
            if node.count_services(f"{name}/{short}"):
                continue  # another node of the same name serves it: DDS would have both, one answers
            node.create_service(srv_type, f"{name}/{short}", callback)

    def _get_node(self) -> Any:
        node = self._node_weak_ref()
        if node is None:
            raise ReferenceError("Expected valid node weak reference")
        return node

    def _describe_parameters_callback(self, request: Any, response: Any) -> Any:
        response.descriptors = _each(request.names, self._get_node().describe_parameter)
        return response

    def _get_parameters_callback(self, request: Any, response: Any) -> Any:
        node = self._get_node()
        response.values = _each(request.names, lambda name: node.get_parameter(name).get_parameter_value())
        return response

    def _get_parameter_types_callback(self, request: Any, response: Any) -> Any:
        response.types = _each(request.names, self._get_node().get_parameter_type)
        return response

    def _list_parameters_callback(self, request: Any, response: Any) -> Any:
        try:
            response.result = self._get_node().list_parameters(list(request.prefixes), request.depth)
        except (TypeError, ValueError):
            response.result = ListParametersResult()
        return response

    def _set_parameters_callback(self, request: Any, response: Any) -> Any:
        node = self._get_node()
        for message in request.parameters:
            response.results.append(self._set_atomically(node, [message]))
        return response

    def _set_parameters_atomically_callback(self, request: Any, response: Any) -> Any:
        response.result = self._set_atomically(self._get_node(), request.parameters)
        return response

    @staticmethod
    def _set_atomically(node: Any, messages: Any) -> SetParametersResult:
        try:
            return node.set_parameters_atomically([Parameter.from_parameter_msg(m) for m in messages])
        except ParameterNotDeclaredException as err:
            return SetParametersResult(successful=False, reason=str(err))


def _each(names: Any, look_up: Any) -> list[Any]:
    """``look_up(name)`` for every name; nothing at all if one is not declared, as rclpy answers."""
    try:
        return [look_up(name) for name in names]
    except (ParameterNotDeclaredException, ParameterUninitializedException):
        return []
