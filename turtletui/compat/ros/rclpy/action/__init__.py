from turtletui.compat.action import ActionClient  # noqa: F401
