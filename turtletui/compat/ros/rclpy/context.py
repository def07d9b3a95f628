from turtletui.compat.context import Context  # noqa: F401
