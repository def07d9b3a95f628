"""``rclpy.parameter.Parameter`` and the rcl_interfaces parameter messages."""

from __future__ import annotations

from enum import Enum
from typing import Any


class ParameterType:
    """Numbers of rcl_interfaces/msg/ParameterType."""

    PARAMETER_NOT_SET = 0
    PARAMETER_BOOL = 1
    PARAMETER_INTEGER = 2
    PARAMETER_DOUBLE = 3
    PARAMETER_STRING = 4
    PARAMETER_BYTE_ARRAY = 5
    PARAMETER_BOOL_ARRAY = 6
    PARAMETER_INTEGER_ARRAY = 7
    PARAMETER_DOUBLE_ARRAY = 8
    PARAMETER_STRING_ARRAY = 9


class ParameterValue:
    """rcl_interfaces/msg/ParameterValue: one typed field holds the value."""

    __slots__ = (
        "type",
        "bool_value",
        "integer_value",
        "double_value",
        "string_value",
        "byte_array_value",
        "bool_array_value",
        "integer_array_value",
        "double_array_value",
        "string_array_value",
    )

    def __init__(self, **kwargs: Any) -> None:
        self.type = 0
        self.bool_value = False
        self.integer_value = 0
        self.double_value = 0.0
        self.string_value = ""
        self.byte_array_value: list = []
        self.bool_array_value: list = []
        self.integer_array_value: list = []
        self.double_array_value: list = []
        self.string_array_value: list = []
        for key, value in kwargs.items():
            if key not in self.__slots__:
                raise AssertionError(f"Invalid arguments passed to constructor: {key}")
            setattr(self, key, value)

    def __repr__(self) -> str:
        return f"rcl_interfaces.msg.ParameterValue(type={self.type}, ...)"


class ParameterDescriptor:
    """rcl_interfaces/msg/ParameterDescriptor (the fields course code sets)."""

    def __init__(
        self,
        *,
        name: str = "",
        type: int = 0,
        description: str = "",
        additional_constraints: str = "",
        read_only: bool = False,
        dynamic_typing: bool = False,
        **_: Any,
    ) -> None:
        self.name = name
        self.type = type
        self.description = description
        self.additional_constraints = additional_constraints
        self.read_only = read_only
        self.dynamic_typing = dynamic_typing


class SetParametersResult:
    """rcl_interfaces/msg/SetParametersResult."""

    def __init__(self, *, successful: bool = False, reason: str = "") -> None:
        self.successful = successful
        self.reason = reason

    def __repr__(self) -> str:
        return f"rcl_interfaces.msg.SetParametersResult(successful={self.successful}, reason={self.reason!r})"


_FIELD = {
    1: "bool_value",
    2: "integer_value",
    3: "double_value",
    4: "string_value",
    5: "byte_array_value",
    6: "bool_array_value",
    7: "integer_array_value",
    8: "double_array_value",
    9: "string_array_value",
}


class Parameter:
    """A named, typed node parameter, as ``rclpy.parameter.Parameter``."""

    class Type(Enum):
        NOT_SET = 0
        BOOL = 1
        INTEGER = 2
        DOUBLE = 3
        STRING = 4
        BYTE_ARRAY = 5
        BOOL_ARRAY = 6
        INTEGER_ARRAY = 7
        DOUBLE_ARRAY = 8
        STRING_ARRAY = 9

        @classmethod
        def from_parameter_value(cls, value: Any) -> Parameter.Type:
            """The type ROS infers for a Python value; TypeError if it has none."""
            if value is None:
                return cls.NOT_SET
            if isinstance(value, bool):
                return cls.BOOL
            if isinstance(value, int):
                return cls.INTEGER
            if isinstance(value, float):
                return cls.DOUBLE
            if isinstance(value, str):
                return cls.STRING
            if isinstance(value, (bytes, bytearray)):
                return cls.BYTE_ARRAY
            if isinstance(value, (list, tuple)):
                if all(isinstance(v, bool) for v in value) and value:
                    return cls.BOOL_ARRAY
                if all(isinstance(v, int) and not isinstance(v, bool) for v in value) and value:
                    return cls.INTEGER_ARRAY
                if all(isinstance(v, float) for v in value) and value:
                    return cls.DOUBLE_ARRAY
                if all(isinstance(v, str) for v in value):
                    return cls.STRING_ARRAY
            raise TypeError(f"The given value is not one of the allowed types '{value!r}'.")

        def check(self, value: Any) -> bool:
            return value is None and self is Parameter.Type.NOT_SET or (
                value is not None and Parameter.Type.from_parameter_value(value) is self
            )

    def __init__(self, name: str, type_: Parameter.Type | None = None, value: Any = None) -> None:
        if type_ is None:
            type_ = Parameter.Type.from_parameter_value(value)
        if not isinstance(type_, Parameter.Type):
            raise TypeError("type must be an instance of Parameter.Type")
        if value is not None and type_ is not Parameter.Type.NOT_SET and not _fits(type_, value):
            raise ValueError(f"Type '{type_}' and value '{value}' do not agree")
        self._name = name
        self._type = type_
        self._value = value

    @property
    def name(self) -> str:
        return self._name

    @property
    def type_(self) -> Parameter.Type:
        return self._type

    @property
    def value(self) -> Any:
        return self._value

    def get_parameter_value(self) -> ParameterValue:
        value = ParameterValue(type=self._type.value)
        field = _FIELD.get(self._type.value)
        if field is not None:
            setattr(value, field, self._value)
        return value

    def __repr__(self) -> str:
        return f"Parameter(name={self._name!r}, type_={self._type}, value={self._value!r})"


def _fits(type_: Parameter.Type, value: Any) -> bool:
    try:
        inferred = Parameter.Type.from_parameter_value(value)
    except TypeError:
        return False
    if inferred is type_:
        return True
    # Empty lists fit any array type.
    return isinstance(value, (list, tuple)) and not value and type_.name.endswith("_ARRAY")


def type_name(value: Any) -> str:
    """ROS's name for the type of a parameter value, e.g. 'INTEGER'."""
    return Parameter.Type.from_parameter_value(value).name
