from turtletui.compat.names import validate_namespace  # noqa: F401
