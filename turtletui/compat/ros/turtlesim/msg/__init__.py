from turtletui.interfaces.turtlesim import Color, Pose  # noqa: F401
