from turtletui.compat.parameter import (  # noqa: F401
    ParameterDescriptor,
    ParameterType,
    ParameterValue,
    SetParametersResult,
)
