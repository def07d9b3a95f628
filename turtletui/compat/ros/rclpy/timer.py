from turtletui.compat.node import Rate, Timer  # noqa: F401
