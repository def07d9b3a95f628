from turtletui.compat.parameter import Parameter  # noqa: F401
