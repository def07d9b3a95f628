"""``rclpy.parameter.Parameter``. Its messages (ParameterValue, ParameterDescriptor,
SetParametersResult, ...) are the rcl_interfaces ones from turtletui.interfaces."""

from __future__ import annotations

import array
from enum import IntEnum
from typing import Any

from turtletui.interfaces.rcl_interfaces import Parameter as ParameterMsg
from turtletui.interfaces.rcl_interfaces import (
    ParameterDescriptor,
    ParameterType,
    ParameterValue,
    SetParametersResult,
)

__all__ = [
    "Parameter",
    "ParameterDescriptor",
    "ParameterType",
    "ParameterValue",
    "SetParametersResult",
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

    def __repr__(self) -> str:
        return f"Parameter(name={self._name!r}, type_={self._type_.name}, value={self._value!r})"


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
    """The Python value held by an rcl_interfaces/msg/ParameterValue."""
    type_ = Parameter.Type(parameter_value.type)
    if type_ is Parameter.Type.NOT_SET:
        return None
    return getattr(parameter_value, _FIELD[type_])


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
