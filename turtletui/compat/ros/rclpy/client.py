from turtletui.compat.node import Client  # noqa: F401
