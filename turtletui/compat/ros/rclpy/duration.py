from turtletui.compat.time import Duration, Infinite  # noqa: F401
