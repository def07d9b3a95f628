"""The parameter services of a node the graph runs itself (turtlesim), as rclcpp serves them:
``<node>/get_parameters``, ``set_parameters`` ... over the node's recorded parameters,
its descriptors and its ``parameter_setter``. Controllers' nodes have rclpy's own
(turtletui.compat.parameter_service)."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

from turtletui.graph.core import Graph, NodeRecord, Service
from turtletui.interfaces import copier
from turtletui.interfaces.rcl_interfaces import (
    DescribeParameters,
    GetParameters,
    GetParameterTypes,
    ListParameters,
    ListParametersResult,
    ParameterDescriptor,
    ParameterType,
    ParameterValue,
    SetParameters,
    SetParametersAtomically,
    SetParametersResult,
)

_T = ParameterType
_FIELDS = {
    _T.PARAMETER_BOOL: "bool_value",
    _T.PARAMETER_INTEGER: "integer_value",
    _T.PARAMETER_DOUBLE: "double_value",
    _T.PARAMETER_STRING: "string_value",
    _T.PARAMETER_BYTE_ARRAY: "byte_array_value",
    _T.PARAMETER_BOOL_ARRAY: "bool_array_value",
    _T.PARAMETER_INTEGER_ARRAY: "integer_array_value",
    _T.PARAMETER_DOUBLE_ARRAY: "double_array_value",
    _T.PARAMETER_STRING_ARRAY: "string_array_value",
}
_WORDS = {
    _T.PARAMETER_NOT_SET: "not set", _T.PARAMETER_BOOL: "bool", _T.PARAMETER_INTEGER: "integer",
    _T.PARAMETER_DOUBLE: "double", _T.PARAMETER_STRING: "string", _T.PARAMETER_BYTE_ARRAY: "byte_array",
    _T.PARAMETER_BOOL_ARRAY: "bool_array", _T.PARAMETER_INTEGER_ARRAY: "integer_array",
    _T.PARAMETER_DOUBLE_ARRAY: "double_array", _T.PARAMETER_STRING_ARRAY: "string_array",
}
"""rclcpp's to_string(ParameterType), as its refusals name types."""


PARAMETER_SERVICES = (
    "describe_parameters",
    "get_parameters",
    "get_parameter_types",
    "list_parameters",
    "set_parameters",
    "set_parameters_atomically",
)
"""What every node serves as ``<node>/<name>`` for its parameters (rclpy's and rclcpp's)."""


def is_parameter_service(service: Service) -> bool:
    """Whether ``service`` is one of its node's parameter services."""
    node, _, short = service.name.rpartition("/")
    return short in PARAMETER_SERVICES and node == service.node.fqn


def list_parameter_names(names: list[str], prefixes: list[str], depth: int) -> ListParametersResult:
    """rclpy 9's Node.list_parameters over ``names``: those under one of ``prefixes``
    (all if none) at most ``depth`` levels deep (0: any depth), and their prefixes."""
    if not isinstance(prefixes, list):
        raise TypeError("The prefixes argument must be a list")
    if not all(isinstance(prefix, str) for prefix in prefixes):
        raise TypeError("All prefixes must be instances of type str")
    if not isinstance(depth, int):
        raise TypeError("The depth must be instance of type int")
    if depth < 0:
        raise ValueError("The depth must be greater than or equal to zero")
    result = ListParametersResult()
    recursive = depth == ListParameters.Request.DEPTH_RECURSIVE

    def shallow(name: str) -> bool:
        return name.count(".") < depth

    for name in names:
        if prefixes or not recursive:
            if not (not prefixes and shallow(name)) and not any(
                name == prefix or (name.startswith(prefix + ".") and (recursive or shallow(name[len(prefix) + 1:])))
                for prefix in prefixes
            ):
                continue
        result.names.append(name)
        prefix = name.rpartition(".")[0]
        if prefix and prefix not in result.prefixes:
            result.prefixes.append(prefix)
    return result


def type_of(value: Any) -> int:
    """The ParameterType of a parameter value as the graph records it."""
    if value is None:
        return _T.PARAMETER_NOT_SET
    for kind, code in ((bool, _T.PARAMETER_BOOL), (int, _T.PARAMETER_INTEGER), (float, _T.PARAMETER_DOUBLE),
                       (str, _T.PARAMETER_STRING)):
        if isinstance(value, kind):
            return code
    items = list(value)
    for kind, code in ((bytes, _T.PARAMETER_BYTE_ARRAY), (bool, _T.PARAMETER_BOOL_ARRAY),
                       (int, _T.PARAMETER_INTEGER_ARRAY), (float, _T.PARAMETER_DOUBLE_ARRAY)):
        if items and all(isinstance(v, kind) for v in items):
            return code
    return _T.PARAMETER_STRING_ARRAY if items else _T.PARAMETER_BYTE_ARRAY


def value_message(value: Any) -> ParameterValue:
    type_ = type_of(value)
    message = ParameterValue(type=type_)
    if type_ != _T.PARAMETER_NOT_SET:
        setattr(message, _FIELDS[type_], list(value) if isinstance(value, tuple) else value)
    return message


def serve_parameters(graph: Graph, node: NodeRecord, descriptors: Mapping[str, ParameterDescriptor]) -> list[Service]:
    """Serve ``node``'s parameters (``descriptors``: one per declared parameter, its
    type filled in) through rclcpp's six parameter services; a set goes through
    ``node.parameter_setter``. Returns the services."""

    def declared(names: Any) -> bool:
        return all(name in node.parameters for name in names)

    def get_parameters(request: Any) -> Any:
        names = list(request.names)
        values = [value_message(node.parameters[n]) for n in names] if declared(names) else []
        return GetParameters.Response(values=values)

    def get_types(request: Any) -> Any:
        names = list(request.names)
        return GetParameterTypes.Response(types=[type_of(node.parameters[n]) for n in names] if declared(names) else [])

    def describe(request: Any) -> Any:
        names = list(request.names)
        copy = copier(ParameterDescriptor)  # the caller's own: changing it changes nothing here
        return DescribeParameters.Response(descriptors=[copy(descriptors[n]) for n in names] if declared(names) else [])

    def list_parameters(request: Any) -> Any:
        return ListParameters.Response(
            result=list_parameter_names(sorted(node.parameters), list(request.prefixes), int(request.depth))
        )

    def set_each(request: Any) -> Any:
        return SetParameters.Response(results=[set_atomically([p]) for p in request.parameters])

    def set_all(request: Any) -> Any:
        return SetParametersAtomically.Response(result=set_atomically(list(request.parameters)))

    def set_atomically(parameters: list[Any]) -> SetParametersResult:
        for parameter in parameters:
            reason = rclcpp_refusal(parameter, descriptors.get(parameter.name), node)
            if reason:
                return SetParametersResult(successful=False, reason=reason)
        for parameter in parameters:
            value = parameter.value
            reason = node.parameter_setter(parameter.name, getattr(value, _FIELDS[value.type]))
            if reason:
                return SetParametersResult(successful=False, reason=reason)
        return SetParametersResult(successful=True)

    def answering(srv_type: Any, answer: Callable[[Any], Any]) -> Callable[[Any, Callable[[Any], None]], None]:
        return lambda request, respond: respond(answer(request))

    name = node.fqn
    return [
        graph.add_service(node, f"{name}/{short}", srv_type, answering(srv_type, answer))
        for short, srv_type, answer in zip(
            PARAMETER_SERVICES,
            (DescribeParameters, GetParameters, GetParameterTypes, ListParameters, SetParameters,
             SetParametersAtomically),
            (describe, get_parameters, get_types, list_parameters, set_each, set_all),
            strict=True,
        )
    ]


def rclcpp_refusal(parameter: Any, descriptor: ParameterDescriptor | None, node: NodeRecord) -> str:
    """Why rclcpp refuses to set ``parameter`` (an rcl_interfaces Parameter) on
    ``node`` whose ``descriptor`` it has (None: undeclared), "" if it would not."""
    name, new_type = parameter.name, parameter.value.type
    if descriptor is None or name not in node.parameters:
        return f"parameter '{name}' cannot be set because it was not declared"
    if descriptor.read_only:
        return f"parameter '{name}' cannot be set because it is read-only"
    if new_type == _T.PARAMETER_NOT_SET:
        return "Static parameter cannot be undeclared"
    if new_type != descriptor.type:
        return (
            f"Wrong parameter type, parameter {{{name}}} is of type {{{_WORDS[descriptor.type]}}}, "
            f"setting it to {{{_WORDS.get(new_type, 'not set')}}} is not allowed."
        )
    if new_type == _T.PARAMETER_INTEGER and descriptor.integer_range:
        bounds = descriptor.integer_range[0]
        value = parameter.value.integer_value
        outside = not bounds.from_value <= value <= bounds.to_value
        off_step = bounds.step != 0 and value not in (bounds.from_value, bounds.to_value) and (
            (value - bounds.from_value) % bounds.step
        )
        if outside or off_step:
            return f"Parameter {{{name}}} doesn't comply with integer range."
    return ""
