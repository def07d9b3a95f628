from turtletui.compat.time import Time  # noqa: F401
