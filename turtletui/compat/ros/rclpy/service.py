from turtletui.compat.node import Service  # noqa: F401
