from turtletui.compat.time import Clock, ClockType, ROSClock  # noqa: F401
