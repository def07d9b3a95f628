"""``rclpy.parameter.Parameter``. Its messages (ParameterValue, ParameterDescriptor,
SetParametersResult, ...) are the rcl_interfaces ones from turtletui.interfaces."""

from __future__ import annotations

import array
import math
from enum import IntEnum
from typing import Any

from turtletui.compat.identity import as_rclpy
from turtletui.graph.parameter_services import list_parameter_names  # noqa: F401  (Node.list_parameters)
from turtletui.interfaces.rcl_interfaces import (
    ListParametersResult,
    ParameterDescriptor,
    ParameterType,
    ParameterValue,
    SetParametersResult,
)
from turtletui.interfaces.rcl_interfaces import Parameter as ParameterMsg

__all__ = [
    "ListParametersResult",
    "Parameter",
    "ParameterDescriptor",
    "ParameterType",
    "ParameterValue",
    "SetParametersResult",
    "get_parameter_value",
    "parameter_dict_from_yaml_file",
    "parameter_value_to_python",
    "type_name",
]


class Parameter:
    """A named, typed node parameter, as ``rclpy.parameter.Parameter``."""

    class Type(IntEnum):
        NOT_SET = ParameterType.PARAMETER_NOT_SET
        BOOL = ParameterType.PARAMETER_BOOL
        INTEGER = ParameterType.PARAMETER_INTEGER
        DOUBLE = ParameterType.PARAMETER_DOUBLE
        STRING = ParameterType.PARAMETER_STRING
        BYTE_ARRAY = ParameterType.PARAMETER_BYTE_ARRAY
        BOOL_ARRAY = ParameterType.PARAMETER_BOOL_ARRAY
        INTEGER_ARRAY = ParameterType.PARAMETER_INTEGER_ARRAY
        DOUBLE_ARRAY = ParameterType.PARAMETER_DOUBLE_ARRAY
        STRING_ARRAY = ParameterType.PARAMETER_STRING_ARRAY

        @classmethod
        def from_parameter_value(cls, parameter_value: Any) -> Parameter.Type:
            """The type rclpy infers for a Python value; TypeError if it has none.

            As in rclpy, an empty list is a BYTE_ARRAY and bools count as integers in a
            list that also holds ints."""
            if parameter_value is None:
                return cls.NOT_SET
            if isinstance(parameter_value, bool):
                return cls.BOOL
            if isinstance(parameter_value, int):
                return cls.INTEGER
            if isinstance(parameter_value, float):
                return cls.DOUBLE
            if isinstance(parameter_value, str):
                return cls.STRING
            if isinstance(parameter_value, (list, tuple, array.array)):
                if all(isinstance(v, bytes) for v in parameter_value):
                    return cls.BYTE_ARRAY
                if all(isinstance(v, bool) for v in parameter_value):
                    return cls.BOOL_ARRAY
                if all(isinstance(v, int) for v in parameter_value):
                    return cls.INTEGER_ARRAY
                if all(isinstance(v, float) for v in parameter_value):
                    return cls.DOUBLE_ARRAY
                if all(isinstance(v, str) for v in parameter_value):
                    return cls.STRING_ARRAY
                raise TypeError(
                    f"The given value is not a list of one of the allowed types '{parameter_value}'."
                )
            raise TypeError(f"The given value is not one of the allowed types '{parameter_value}'.")

        def check(self, parameter_value: Any) -> bool:
            """Whether ``parameter_value`` may be the value of a parameter of this type."""
            T = Parameter.Type
            if self is T.NOT_SET:
                return parameter_value is None
            if self is T.BOOL:
                return isinstance(parameter_value, bool)
            if self is T.INTEGER:
                return isinstance(parameter_value, int)
            if self is T.DOUBLE:
                return isinstance(parameter_value, float)
            if self is T.STRING:
                return isinstance(parameter_value, str)
            sequence = isinstance(parameter_value, (list, tuple))
            numbers = isinstance(parameter_value, (list, tuple, array.array))
            if self is T.BYTE_ARRAY:
                return sequence and all(isinstance(v, bytes) and len(v) == 1 for v in parameter_value)
            if self is T.BOOL_ARRAY:
                return sequence and all(isinstance(v, bool) for v in parameter_value)
            if self is T.INTEGER_ARRAY:
                return numbers and all(isinstance(v, int) for v in parameter_value)
            if self is T.DOUBLE_ARRAY:
                return numbers and all(isinstance(v, float) for v in parameter_value)
            if self is T.STRING_ARRAY:
                return sequence and all(isinstance(v, str) for v in parameter_value)
            return False

    @classmethod
    def from_parameter_msg(cls, param_msg: Any) -> Parameter:
        type_ = Parameter.Type(param_msg.value.type)
        field = _FIELD.get(type_)
        return cls(param_msg.name, type_, getattr(param_msg.value, field) if field else None)

    def __init__(self, name: str, type_: Parameter.Type | None = None, value: Any = None) -> None:
        if type_ is None:
            type_ = Parameter.Type.from_parameter_value(value)
        if not isinstance(type_, Parameter.Type):
            raise TypeError(f"type must be an instance of '{Parameter.Type!r}'")
        if not type_.check(value):
            raise ValueError(f"Type '{type_}' and value '{value}' do not agree")
        self._name = name
        self._type_ = type_
        self._value = value

    @property
    def name(self) -> str:
        return self._name

    @property
    def type_(self) -> Parameter.Type:
        return self._type_

    @property
    def value(self) -> Any:
        return self._value

    def get_parameter_value(self) -> ParameterValue:
        """The value as an rcl_interfaces/msg/ParameterValue (``.double_value``, ...)."""
        parameter_value = ParameterValue(type=self._type_.value)
        field = _FIELD.get(self._type_)
        if field is not None:
            value = self._value
            # rclpy's checks let bools through as integers; the message field wants ints.
            if self._type_ is Parameter.Type.INTEGER:
                value = int(value)
            elif self._type_ is Parameter.Type.INTEGER_ARRAY:
                value = [int(v) for v in value]
            setattr(parameter_value, field, value)
        return parameter_value

    def to_parameter_msg(self) -> ParameterMsg:
        return ParameterMsg(name=self.name, value=self.get_parameter_value())


_FIELD = {
    Parameter.Type.BOOL: "bool_value",
    Parameter.Type.INTEGER: "integer_value",
    Parameter.Type.DOUBLE: "double_value",
    Parameter.Type.STRING: "string_value",
    Parameter.Type.BYTE_ARRAY: "byte_array_value",
    Parameter.Type.BOOL_ARRAY: "bool_array_value",
    Parameter.Type.INTEGER_ARRAY: "integer_array_value",
    Parameter.Type.DOUBLE_ARRAY: "double_array_value",
    Parameter.Type.STRING_ARRAY: "string_array_value",
}


def parameter_value_to_python(parameter_value: ParameterValue) -> Any:
    """The Python value held by an rcl_interfaces/msg/ParameterValue: arrays as lists,
    as rclpy's; an unknown type raises rclpy's RuntimeError."""
    try:
        type_ = Parameter.Type(parameter_value.type)
    except ValueError:
        raise RuntimeError(f"unexpected parameter type {parameter_value.type}") from None
    if type_ is Parameter.Type.NOT_SET:
        return None
    value = getattr(parameter_value, _FIELD[type_])
    return list(value) if type_.name.endswith("_ARRAY") else value


def type_of(value: Any) -> Parameter.Type | None:
    """``Parameter.Type.from_parameter_value``, or None for a value with no ROS type."""
    try:
        return Parameter.Type.from_parameter_value(value)
    except TypeError:
        return None


def type_matches(expected: Parameter.Type, value: Any) -> bool:
    """Whether ``value`` (e.g. a ``-p`` override) has the type a parameter was declared with;
    an empty list fits any array type."""
    if type_of(value) is expected:
        return True
    return isinstance(value, (list, tuple)) and not value and expected.name.endswith("_ARRAY")


def type_name(value: Any) -> str:
    """ROS's name for the type of a parameter value, e.g. 'INTEGER'."""
    return Parameter.Type.from_parameter_value(value).name


def apply_descriptor(
    parameter: Parameter,
    descriptor: ParameterDescriptor,
    *,
    declared: bool,
    rel_tol: float,
    check_read_only: bool = True,
) -> SetParametersResult:
    """Whether ``parameter`` may be set under ``descriptor`` (read-only, type, range
    and step), with rclpy 9's reasons (Node._apply_descriptor); ``declared``: the
    parameter exists already. A dynamically typed descriptor takes the parameter's type."""
    descriptor.name = parameter.name
    if check_read_only and descriptor.read_only:
        return _refused(f"Trying to set a read-only parameter: {parameter.name}.")
    NOT_SET = Parameter.Type.NOT_SET
    if descriptor.dynamic_typing:
        descriptor.type = parameter.type_.value
    elif declared and parameter.type_ is NOT_SET:
        return _refused("Static parameter cannot be undeclared")
    elif parameter.type_ is not NOT_SET and parameter.type_.value != descriptor.type:
        return _refused(
            # as rclpy's, an IntEnum's str(): '3' from Python 3.11 on
            f"Wrong parameter type, expected '{Parameter.Type(descriptor.type)}' got '{parameter.type_}'"
        )
    if parameter.type_ is Parameter.Type.INTEGER and descriptor.integer_range:
        return _in_range(parameter, descriptor.integer_range[0], lambda a, b: a == b, ". Min")
    if parameter.type_ is Parameter.Type.DOUBLE and descriptor.floating_point_range:
        return _in_range(
            parameter,
            descriptor.floating_point_range[0],
            lambda a, b: math.isclose(a, b, rel_tol=rel_tol),
            " Min",
        )
    return SetParametersResult(successful=True)


def _refused(reason: str) -> SetParametersResult:
    return SetParametersResult(successful=False, reason=reason)


def _in_range(parameter: Parameter, bounds: Any, same: Any, out_of_range: str) -> SetParametersResult:
    """rclpy's _apply_integer_range / _apply_floating_point_range (``out_of_range``
    is what follows "out of range" in each: rclpy's two texts differ)."""
    value = parameter.value
    low, high = min(bounds.from_value, bounds.to_value), max(bounds.from_value, bounds.to_value)
    if same(value, low) or same(value, high):
        return SetParametersResult(successful=True)
    if not low < value < high:
        return _refused(f"Parameter {parameter.name} out of range{out_of_range}: {low}, Max: {high}, value: {value}")
    step = bounds.step
    if isinstance(value, int) and not isinstance(value, bool):
        if step != 0 and (value - low) % step != 0:
            return _refused(
                f"The parameter value for {parameter.name} is not a valid step. "
                f"Min: {low}, max: {high}, value: {value}, step: {step}"
            )
    elif step != 0.0 and not same(low + round((value - low) / step) * step, value):
        return _refused(
            f"The parameter value for {parameter.name} is not close enough to a valid step. "
            f"Min: {low}, max: {high}, value: {value}, step: {step}"
        )
    return SetParametersResult(successful=True)


def get_parameter_value(string_value: str) -> ParameterValue:
    """The ParameterValue a string reads as in YAML (rclpy's guess of its type)."""
    import yaml

    try:
        yaml_value = yaml.safe_load(string_value)
    except yaml.parser.ParserError:  # only this one, as rclpy: a ScannerError ('a: b: c') goes on
        yaml_value = string_value
    if isinstance(yaml_value, list):
        for type_ in (Parameter.Type.BOOL_ARRAY, Parameter.Type.INTEGER_ARRAY,
                      Parameter.Type.DOUBLE_ARRAY, Parameter.Type.STRING_ARRAY):
            if type_.check(yaml_value) or (type_ is Parameter.Type.INTEGER_ARRAY and _all_ints(yaml_value)):
                return Parameter("", type_, yaml_value).get_parameter_value()
        return ParameterValue(type=ParameterType.PARAMETER_STRING, string_value=string_value)
    if isinstance(yaml_value, (bool, int, float)):
        return Parameter("", value=yaml_value).get_parameter_value()
    text = yaml_value if isinstance(yaml_value, str) else string_value
    return ParameterValue(type=ParameterType.PARAMETER_STRING, string_value=text)


def _all_ints(values: list) -> bool:
    return all(isinstance(v, int) for v in values)  # bools too, as in rclpy


def parameter_dict_from_yaml_file(
    parameter_file: str, use_wildcard: bool = False, target_nodes: list[str] | None = None, namespace: str = ""
) -> dict[str, ParameterMsg]:
    """rclpy's: the parameters a YAML parameter file gives ``target_nodes`` (and
    ``/**`` with ``use_wildcard``), as rcl_interfaces Parameter messages keyed by
    name; RuntimeError when the file is not a ROS parameter file for them."""
    import yaml

    with open(parameter_file) as stream:
        param_file = yaml.safe_load(stream)
    if not isinstance(param_file, dict):
        raise RuntimeError("YAML file is not a valid ROS parameter file")
    param_dict: dict[str, Any] = {}

    def section(value: Any, what: str) -> dict:
        if not isinstance(value, dict) or not isinstance(value.get("ros__parameters"), dict):
            raise RuntimeError(f"YAML file is not a valid ROS parameter file for {what}")
        return value["ros__parameters"]

    if use_wildcard and "/**" in param_file:
        param_dict.update(section(param_file["/**"], "wildcard(/**)"))
    if target_nodes:
        for node in target_nodes:
            if not node:
                continue
            absolute = node if node.startswith("/") else f"/{node}"
            if absolute in param_file:
                param_dict.update(section(param_file[absolute], f"node {absolute}"))
            ns, basename = absolute.rsplit("/", 1)
            if not ns and basename in param_file:
                param_dict.update(section(param_file[basename], f"node {basename}"))
            elif ns in param_file and isinstance(param_file[ns], dict) and basename in param_file[ns]:
                param_dict.update(section(param_file[ns][basename], f"namespace {ns} node {basename}"))
    if not param_dict:
        raise RuntimeError("Param file does not contain any valid parameters")
    return _unpack(namespace, param_dict)


def _unpack(namespace: str, parameter_dict: dict) -> dict[str, ParameterMsg]:
    parameters: dict[str, ParameterMsg] = {}
    for name, value in parameter_dict.items():
        full_name = namespace + str(name)
        if isinstance(value, dict):
            parameters.update(_unpack(full_name + ".", value))
        else:
            parameters[full_name] = ParameterMsg(name=full_name, value=get_parameter_value(str(value)))
    return parameters

# as rclpy's classes print: <rclpy.node.Node object at ...> (turtletui.compat.identity)
as_rclpy("rclpy.parameter", Parameter)
