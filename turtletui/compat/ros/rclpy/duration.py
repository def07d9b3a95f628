from turtletui.compat.time import Duration  # noqa: F401
