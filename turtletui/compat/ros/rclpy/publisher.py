from turtletui.compat.node import Publisher  # noqa: F401
