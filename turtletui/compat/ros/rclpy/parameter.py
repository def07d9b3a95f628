from turtletui.compat.parameter import Parameter, parameter_value_to_python  # noqa: F401
