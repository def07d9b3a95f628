from turtletui.compat.time import ClockType  # noqa: F401
